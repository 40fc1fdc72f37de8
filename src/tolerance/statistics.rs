//! The statistics of a Monte Carlo output: count, mean, standard
//! deviation, smallest and largest, accumulated one sample at a time
//! (Welford's update, which keeps the variance's digits where the naive
//! sum of squares cancels them).

/// The statistics of one output's samples.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Statistics {
    pub count: usize,
    pub mean: f64,
    /// The sum of squared deviations from the mean (Welford's M2).
    sum_of_squares: f64,
    pub min: f64,
    pub max: f64,
}

impl Default for Statistics {
    fn default() -> Statistics {
        Statistics {
            count: 0,
            mean: 0.0,
            sum_of_squares: 0.0,
            min: f64::INFINITY,
            max: f64::NEG_INFINITY,
        }
    }
}

impl Statistics {
    /// Adds a sample.
    pub fn push(&mut self, x: f64) {
        self.count += 1;
        let delta = x - self.mean;
        self.mean += delta / self.count as f64;
        self.sum_of_squares += delta * (x - self.mean);
        self.min = self.min.min(x);
        self.max = self.max.max(x);
    }

    /// The statistics of `samples`.
    pub fn of(samples: impl IntoIterator<Item = f64>) -> Statistics {
        let mut statistics = Statistics::default();
        samples.into_iter().for_each(|x| statistics.push(x));
        statistics
    }

    /// The sample standard deviation (0 for fewer than two samples).
    pub fn std(&self) -> f64 {
        if self.count < 2 {
            0.0
        } else {
            (self.sum_of_squares / (self.count - 1) as f64).sqrt()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn welford_keeps_the_variance_of_a_large_offset() {
        // 1e9 + {1, 2, 3, 4}: variance 5/3, which the sum of squares loses.
        let s = Statistics::of([1.0, 2.0, 3.0, 4.0].map(|x| 1e9 + x));
        assert_eq!(s.count, 4);
        assert_eq!(s.mean, 1e9 + 2.5);
        assert!((s.std() - (5.0f64 / 3.0).sqrt()).abs() < 1e-15);
        assert_eq!((s.min, s.max), (1e9 + 1.0, 1e9 + 4.0));
        assert_eq!(Statistics::of([3.0]).std(), 0.0);
    }
}
