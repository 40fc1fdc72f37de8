//! The Monte Carlo samples: each a function of its run's random state and its index
//! alone, so that a run gives the same samples on any number of threads
//! and any sample can be drawn again by itself.
//!
//! A SplitMix64 stream per sample ([`crate::random`]), started at a state
//! mixed from the random state and the index.

use super::{Tolerance, Tolerances};
use crate::random::SplitMix64;
use nalgebra::SVector;

impl<const K: usize> Tolerances<K> {
    /// The deviation of the parameters in Monte Carlo sample `index` of the
    /// run of random state `random_state`: uniform within each band, normal with each σ.
    pub fn deviation(&self, random_state: u64, index: usize) -> SVector<f64, K> {
        let mut stream = SplitMix64::of_sample(random_state, index as u64);
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
        // Reproducible by index, different between indices and random states.
        assert_eq!(tolerances.deviation(7, 12), tolerances.deviation(7, 12));
        assert_ne!(tolerances.deviation(7, 12), tolerances.deviation(7, 13));
        assert_ne!(tolerances.deviation(7, 12), tolerances.deviation(8, 12));
    }
}
