//! An axis: its range from the data (or as given), its ticks and their
//! labels, and where a value falls on the page.

use super::panel::Scale;
use super::text;

/// An axis laid out: the range it shows and its ticks.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Axis {
    pub(crate) scale: Scale,
    /// The range shown, in the data's units.
    pub(crate) range: (f64, f64),
    /// The ticks: where (in the data's units) and their labels (empty for
    /// a tick without one).
    pub(crate) ticks: Vec<(f64, String)>,
}

impl Axis {
    /// An axis showing `range` with about `room` ticks at most.
    pub(crate) fn new(scale: Scale, range: (f64, f64), room: usize) -> Axis {
        let ticks = match scale {
            Scale::Linear => linear_ticks(range, room),
            Scale::Log => log_ticks(range, room),
        };
        Axis {
            scale,
            range,
            ticks,
        }
    }

    /// Where `value` falls between `from` (the range's low end) and `to`
    /// (its high end), in pixels.
    pub(crate) fn place(&self, value: f64, from: f64, to: f64) -> f64 {
        let (lo, hi, v) = match self.scale {
            Scale::Linear => (self.range.0, self.range.1, value),
            Scale::Log => (
                self.range.0.log10(),
                self.range.1.log10(),
                value.max(f64::MIN_POSITIVE).log10(),
            ),
        };
        from + (v - lo) / (hi - lo) * (to - from)
    }

    /// The widest tick label, as drawn at `size`.
    pub(crate) fn widest_label(&self, size: f64) -> f64 {
        self.ticks
            .iter()
            .map(|(_, label)| text::width(label, size))
            .fold(0.0, f64::max)
    }
}

/// The range of `values` on `scale`, widened by `margin` of its span each
/// way; at least a millionth of the values' size wide, so that it has
/// ticks to draw (±1 about zero, a decade each way on a log scale).
pub(crate) fn range_of(values: impl Iterator<Item = f64>, scale: Scale, margin: f64) -> (f64, f64) {
    let to_axis = |v: f64| match scale {
        Scale::Linear => v,
        Scale::Log => v.log10(),
    };
    let (lo, hi) = values
        .filter(|v| scale == Scale::Linear || *v > 0.0)
        .map(to_axis)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    let (lo, hi) = if lo.is_finite() && hi.is_finite() {
        (lo, hi)
    } else {
        (0.0, 1.0)
    };
    let least = (1e-6 * lo.abs().max(hi.abs())).max(1e-300);
    let (lo, hi) = if hi - lo >= least {
        let d = margin * (hi - lo);
        (lo - d, hi + d)
    } else {
        let middle = 0.5 * lo + 0.5 * hi;
        let half = if middle == 0.0 || scale == Scale::Log {
            1.0
        } else {
            least
        };
        (middle - half, middle + half)
    };
    match scale {
        Scale::Linear => (lo, hi),
        Scale::Log => (10f64.powf(lo), 10f64.powf(hi)),
    }
}

/// The step of about `room` ticks over `span` (one more at most): 1, 2
/// or 5 × 10ᵏ.
fn nice_step(span: f64, room: usize) -> f64 {
    let raw = span / room.max(2) as f64;
    let decade = 10f64.powf(raw.log10().floor());
    let most = (room.max(2) + 1) as f64;
    [0.5, 1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * decade)
        .find(|&s| span / s <= most)
        .unwrap_or(10.0 * decade)
}

fn linear_ticks((lo, hi): (f64, f64), room: usize) -> Vec<(f64, String)> {
    let mut step = nice_step(hi - lo, room);
    // Three labels at least, so that the scale can be read.
    while ((hi / step).floor() - (lo / step).ceil()) < 2.0 {
        let mantissa = step / 10f64.powf(step.log10().floor());
        step *= if (mantissa - 5.0).abs() < 1e-9 {
            0.4
        } else {
            0.5
        };
    }
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last)
        .map(|k| {
            let x = k as f64 * step;
            (x, text::tick(x, step))
        })
        .collect()
}

fn log_ticks((lo, hi): (f64, f64), room: usize) -> Vec<(f64, String)> {
    let (a, b) = (lo.log10(), hi.log10());
    if b - a < 1.0 {
        // Less than a decade: the linear ticks, on the log scale.
        return linear_ticks((lo, hi), room.min(5));
    }
    if b - a < 2.5 {
        // Two decades or so: 1, 2 and 5 of each, labelled.
        let mut ticks = Vec::new();
        for e in (a.floor() as i32)..=(b.ceil() as i32) {
            for m in [1.0, 2.0, 5.0] {
                let x = m * 10f64.powi(e);
                if (lo..=hi).contains(&x) {
                    let step = 10f64.powi(e);
                    ticks.push((x, text::tick(x, step)));
                }
            }
        }
        return ticks;
    }
    let first = a.ceil() as i32;
    let last = b.floor() as i32;
    let decades = (last - first + 1).max(1) as usize;
    let every = decades.div_ceil(room.max(2)).max(1) as i32;
    let labelled = (first..=last).filter(|e| (e - first) % every == 0);
    let plain = labelled.clone().all(|e| (-2..=2).contains(&e));
    (first..=last)
        .map(|e| {
            let label = if (e - first) % every == 0 {
                text::decade(e, plain)
            } else {
                String::new()
            };
            (10f64.powi(e), label)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_ticks_are_round() {
        let axis = Axis::new(Scale::Linear, (-0.3, 2.2), 6);
        let labels: Vec<&str> = axis.ticks.iter().map(|t| t.1.as_str()).collect();
        assert_eq!(labels, ["0", "0.5", "1.0", "1.5", "2.0"]);
        let axis = Axis::new(Scale::Linear, (0.0, 360.0), 8);
        assert_eq!(axis.ticks.len(), 8);
        assert_eq!(axis.ticks[7].1, "350");
    }

    #[test]
    fn log_ticks_are_decades() {
        let axis = Axis::new(Scale::Log, (1e-13, 0.2), 6);
        assert!(axis.ticks.iter().all(|t| t.0 > 1e-14));
        let labelled: Vec<&str> = axis
            .ticks
            .iter()
            .filter(|t| !t.1.is_empty())
            .map(|t| t.1.as_str())
            .collect();
        assert_eq!(labelled, ["10⁻¹³", "10⁻¹⁰", "10⁻⁷", "10⁻⁴", "10⁻¹"]);
        let place = axis.place(1e-6, 0.0, 100.0);
        let expected = (-6.0 + 13.0) / (0.2f64.log10() + 13.0) * 100.0;
        assert!((place - expected).abs() < 1e-12);
    }

    #[test]
    fn short_log_axes_have_ones_twos_and_fives() {
        let axis = Axis::new(Scale::Log, (1.0, 40.0), 6);
        let labels: Vec<&str> = axis.ticks.iter().map(|t| t.1.as_str()).collect();
        assert_eq!(labels, ["1", "2", "5", "10", "20"]);
    }

    #[test]
    fn ranges() {
        assert_eq!(
            range_of([1.0, 3.0].into_iter(), Scale::Linear, 0.0),
            (1.0, 3.0)
        );
        assert_eq!(
            range_of([0.0, 0.0].into_iter(), Scale::Linear, 0.1),
            (-1.0, 1.0)
        );
        let (lo, hi) = range_of([1e-3, 10.0, -1.0].into_iter(), Scale::Log, 0.0);
        assert!((lo - 1e-3).abs() < 1e-15 && (hi - 10.0).abs() < 1e-12);
    }
}
