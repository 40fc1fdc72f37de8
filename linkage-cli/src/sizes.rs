//! From a mechanism whose sizes are known at run time to the analyses,
//! which are compiled for sizes known at compile time: a job is run on the
//! mechanism seen at its own sizes, among the sizes this tool is built
//! for. Each size instantiates every analysis once, so the list is what
//! mechanisms are usually made of, not every size there is; a mechanism
//! of another size is promoted to Rust with `linkage expand`, where the
//! attribute compiles it at its own sizes.

use crate::failure::Failure;
use linkage::mechanism::{Fixed, Mechanism};

/// Work to do on a mechanism at its sizes.
pub trait Job {
    type Output;
    fn run<const M: usize, const F: usize>(
        self,
        mechanism: Fixed<M, F>,
    ) -> Result<Self::Output, Failure>;
}

/// The sizes (m, f) this tool is built for.
pub const SIZES: &[(usize, usize)] = &[
    (1, 1),
    (2, 1),
    (3, 1),
    (4, 1),
    (5, 1),
    (6, 1),
    (7, 1),
    (8, 1),
    (10, 1),
    (12, 1),
    (16, 1),
    (1, 2),
    (2, 2),
    (3, 2),
    (4, 2),
    (5, 2),
    (6, 2),
];

macro_rules! at_sizes {
    ($mechanism:expr, $job:expr; $(($m:literal, $f:literal)),*) => {
        match ($mechanism.m(), $mechanism.f()) {
            $(($m, $f) => {
                let fixed = $mechanism.fixed::<$m, $f>().map_err(|e| Failure::Analysis(e.to_string()))?;
                $job.run(fixed)
            })*
            (m, f) => Err(Failure::Analysis(format!(
                "this tool analyses mechanisms of the sizes {}; this one has m = {m}, f = {f}: \
                 promote it to Rust with `linkage expand`",
                SIZES.iter().map(|(m, f)| format!("({m}, {f})")).collect::<Vec<_>>().join(" ")
            ))),
        }
    };
}

/// Runs `job` on `mechanism` at its sizes.
pub fn run<J: Job>(mechanism: &Mechanism, job: J) -> Result<J::Output, Failure> {
    at_sizes!(mechanism, job;
        (1, 1), (2, 1), (3, 1), (4, 1), (5, 1), (6, 1), (7, 1), (8, 1), (10, 1), (12, 1), (16, 1),
        (1, 2), (2, 2), (3, 2), (4, 2), (5, 2), (6, 2))
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Sizes;
    impl Job for Sizes {
        type Output = (usize, usize);
        fn run<const M: usize, const F: usize>(
            self,
            _: Fixed<M, F>,
        ) -> Result<(usize, usize), Failure> {
            Ok((M, F))
        }
    }

    /// The list says what the match does: every listed size dispatches to
    /// itself, and one more is refused with the list.
    #[test]
    fn every_listed_size_runs_at_its_size() {
        for &(m, f) in SIZES {
            let u: Vec<String> = (0..m).map(|k| format!("x{k}")).collect();
            let v: Vec<String> = (0..f).map(|k| format!("t{k}")).collect();
            let closure: Vec<String> = (0..m).map(|k| format!("x{k} - t0")).collect();
            let text = format!(
                "u = [{}], v = [{}], closure = [{}]",
                u.join(", "),
                v.join(", "),
                closure.join(", ")
            );
            let mechanism = Mechanism::from_text("Sizes", &text, &[]).unwrap();
            assert_eq!(run(&mechanism, Sizes).unwrap(), (m, f));
        }
        let text = "u = [x0, x1, x2, x3, x4, x5, x6, x7, x8], v = [t], closure = [x0 - t, x1, x2, x3, x4, x5, x6, x7, x8]";
        let nine = Mechanism::from_text("Nine", text, &[]).unwrap();
        let Err(Failure::Analysis(why)) = run(&nine, Sizes) else {
            panic!("m = 9 is not a size of the tool");
        };
        assert!(why.contains("m = 9, f = 1"), "{why}");
    }
}
