//! The campaign's random numbers: SplitMix64, one generator per case,
//! started from the campaign's constant and the case's index, so that a
//! case is reproduced by its index alone.

pub(crate) struct Rng(u64);

impl Rng {
    /// The generator of case `index` of the campaign `campaign`.
    pub(crate) fn for_case(campaign: u64, index: u64) -> Rng {
        let mut rng = Rng(campaign ^ index.wrapping_mul(0x9e37_79b9_7f4a_7c15));
        rng.next();
        rng
    }

    pub(crate) fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A number in `0..n` (`n` > 0).
    pub(crate) fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    /// A number in `lo..=hi`.
    pub(crate) fn between(&mut self, lo: usize, hi: usize) -> usize {
        lo + self.below(hi - lo + 1)
    }

    /// True one time in `n`.
    pub(crate) fn one_in(&mut self, n: usize) -> bool {
        self.below(n) == 0
    }

    /// A uniform number in [0, 1).
    pub(crate) fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    pub(crate) fn pick<'a, T>(&mut self, xs: &'a [T]) -> &'a T {
        &xs[self.below(xs.len())]
    }

    /// A small count, mostly 1, now and then up to `most`.
    pub(crate) fn few(&mut self, most: usize) -> usize {
        let mut n = 1;
        while n < most && self.one_in(2) {
            n += 1;
        }
        n
    }
}
