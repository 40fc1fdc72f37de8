//! The Monte Carlo samples: each a function of the seed and its index
//! alone, so that a run gives the same samples on any number of threads
//! and any sample can be drawn again by itself.
//!
//! A SplitMix64 stream per sample (Steele, Lea and Flood 2014: a 64-bit
//! counter through a bijective mixer, the generator that seeds the
//! xoshiro family), started at a state mixed from the seed and the index;
//! uniform numbers in (0, 1) from its top 53 bits, normal ones by the
//! Box–Muller transform.

use super::{Tolerance, Tolerances};
use nalgebra::SVector;
use std::f64::consts::TAU;

/// The SplitMix64 generator.
struct SplitMix64(u64);

impl SplitMix64 {
    const GOLDEN: u64 = 0x9e37_79b9_7f4a_7c15;

    /// The stream of sample `index` of the run `seed`.
    fn of_sample(seed: u64, index: u64) -> SplitMix64 {
        let mut mixer = SplitMix64(seed);
        let start = mixer.next() ^ index.wrapping_mul(Self::GOLDEN);
        let mut stream = SplitMix64(start);
        stream.next();
        stream
    }

    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(Self::GOLDEN);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in the open interval (0, 1).
    fn uniform(&mut self) -> f64 {
        ((self.next() >> 11) as f64 + 0.5) * (1.0 / (1u64 << 53) as f64)
    }

    /// Standard normal (Box–Muller, one of the pair).
    fn normal(&mut self) -> f64 {
        let (a, b) = (self.uniform(), self.uniform());
        (-2.0 * a.ln()).sqrt() * (TAU * b).cos()
    }
}

impl<const K: usize> Tolerances<K> {
    /// The deviation of the parameters in Monte Carlo sample `index` of the
    /// run `seed`: uniform within each band, normal with each σ.
    pub fn deviation(&self, seed: u64, index: usize) -> SVector<f64, K> {
        let mut stream = SplitMix64::of_sample(seed, index as u64);
        SVector::from_fn(|i, _| match self.get(i) {
            Tolerance::Band(t) => t * (2.0 * stream.uniform() - 1.0),
            Tolerance::Normal(sigma) => sigma * stream.normal(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splitmix64_gives_the_reference_sequence() {
        // The first outputs of SplitMix64 from state 0 (0xe220a8397b1dcdaf
        // is the commonly quoted first one; the others from a Python
        // transcription of the authors' splitmix64.c).
        let mut g = SplitMix64(0);
        assert_eq!(g.next(), 0xe220_a839_7b1d_cdaf);
        assert_eq!(g.next(), 0x6e78_9e6a_a1b9_65f4);
        assert_eq!(g.next(), 0x06c4_5d18_8009_454f);
    }

    #[test]
    fn samples_fill_their_bands_with_the_right_moments() {
        let tolerances = Tolerances::new([
            Tolerance::Band(2.0),
            Tolerance::Normal(0.5),
            Tolerance::EXACT,
        ])
        .unwrap();
        let n = 200_000;
        let (mut mean, mut square) = (SVector::<f64, 3>::zeros(), SVector::<f64, 3>::zeros());
        let mut widest: f64 = 0.0;
        for k in 0..n {
            let d = tolerances.deviation(7, k);
            widest = widest.max(d[0].abs());
            mean += d;
            square += d.component_mul(&d);
        }
        mean /= n as f64;
        square /= n as f64;
        // Uniform on ±2: mean 0, variance 4/3; normal: variance 0.25.
        assert!(widest <= 2.0 && widest > 1.999);
        assert!(mean[0].abs() < 0.01 && mean[1].abs() < 0.005, "{mean}");
        assert!((square[0] / (4.0 / 3.0) - 1.0).abs() < 0.01, "{square}");
        assert!((square[1] / 0.25 - 1.0).abs() < 0.01, "{square}");
        assert_eq!(square[2], 0.0);
        // Reproducible by index, different between indices and seeds.
        assert_eq!(tolerances.deviation(7, 12), tolerances.deviation(7, 12));
        assert_ne!(tolerances.deviation(7, 12), tolerances.deviation(7, 13));
        assert_ne!(tolerances.deviation(7, 12), tolerances.deviation(8, 12));
    }
}
