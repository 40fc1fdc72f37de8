//! What every area's campaign shares: the runner, the watchdog, the awkward
//! numbers and counts, the tally, the checks of an `Ok`, and the
//! worksheet's four-bar made of awkward lengths.

use crate::common::FourBar;
use proptest::test_runner::{Config, RngSeed, TestCaseError, TestRunner};
use std::cell::RefCell;
use std::collections::BTreeMap;
use std::time::{Duration, Instant};

pub(crate) fn cases() -> u32 {
    std::env::var("LINKAGE_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(300)
}

pub(crate) fn runner(cases: u32) -> TestRunner {
    let mut config = Config::with_cases(cases.max(1));
    config.failure_persistence = None;
    // A hang shrinks slowly: a minute of shrinking at most.
    config.max_shrink_time = 60_000;
    if std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        config.rng_seed = RngSeed::Fixed(0x6661_6361_6465);
    }
    TestRunner::new(config)
}

pub(crate) use crate::watchdog::{Ended, time_limit, watched};

/// An awkward number from 64 random bits: an arbitrary bit pattern, a
/// special value, or an ordinary number of either sign.
pub(crate) fn awkward(bits: u64) -> f64 {
    const SPECIAL: [f64; 12] = [
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        0.0,
        -0.0,
        f64::MAX,
        -f64::MAX,
        f64::MIN_POSITIVE,
        5e-324,
        1e300,
        -1e-300,
        1.0,
    ];
    let pick = bits >> 60;
    let rest = bits & ((1 << 60) - 1);
    match pick {
        0..=3 => f64::from_bits(bits.rotate_left(7)),
        4..=6 => SPECIAL[(rest % SPECIAL.len() as u64) as usize],
        _ => {
            // ±10^(−3 … 3), some of them whole.
            let exponent = (rest % 6001) as f64 / 1000.0 - 3.0;
            let sign = if rest & (1 << 40) != 0 { -1.0 } else { 1.0 };
            let x = sign * 10f64.powf(exponent);
            if rest & (1 << 41) != 0 { x.round() } else { x }
        }
    }
}

/// A count: small ones mostly, some huge.
pub(crate) fn count(bits: u64) -> usize {
    match bits % 8 {
        0 => 0,
        1 => usize::MAX,
        2 => u32::MAX as usize,
        3 => (bits >> 8) as usize % 100_000,
        _ => (bits >> 8) as usize % 200,
    }
}

/// The numbers of one world: all ordinary (a third of the worlds), all
/// ordinary but one awkward (a third), or all awkward — so that the code
/// behind the checks of the settings is reached, with every awkward number
/// in every place.
pub(crate) struct Numbers<const N: usize> {
    pub(crate) bits: [u64; N],
}

impl<const N: usize> Numbers<N> {
    /// The k-th number, `usual` when ordinary.
    pub(crate) fn get(&self, k: usize, usual: f64) -> f64 {
        let mode = self.bits[0] % 3;
        let spoilt = (self.bits[0] >> 2) as usize % N;
        match mode {
            0 => usual,
            1 if k != spoilt => usual,
            _ => awkward(self.bits[k].rotate_left(11)),
        }
    }
}

pub(crate) fn finite(xs: impl IntoIterator<Item = f64>) -> bool {
    xs.into_iter().all(f64::is_finite)
}

/// An SVG without a non-finite number written into it.
pub(crate) fn clean_svg(svg: &str) -> bool {
    for word in ["NaN", "inf"] {
        if let Some(at) = svg.find(word) {
            let from = svg[..at].char_indices().rev().nth(80).map_or(0, |(i, _)| i);
            let to = svg[at..]
                .char_indices()
                .nth(40)
                .map_or(svg.len(), |(i, _)| at + i);
            eprintln!("a non-finite number in an SVG: …{:?}…", &svg[from..to]);
            return false;
        }
    }
    true
}

/// What a campaign found.
#[derive(Default)]
pub(crate) struct Tally {
    cases: usize,
    ok: usize,
    errors: BTreeMap<String, usize>,
    slowest: Duration,
}

impl Tally {
    fn error(&mut self, e: &dyn std::fmt::Debug) {
        let text = format!("{e:?}");
        let kind = text
            .split(|c: char| !c.is_alphanumeric())
            .find(|s| !s.is_empty())
            .unwrap_or("?")
            .to_string();
        *self.errors.entry(kind).or_default() += 1;
    }

    pub(crate) fn report(&self, name: &str, started: Instant) {
        eprintln!(
            "{name}: {} cases in {:.1} s (slowest {:.2} s), {} Ok, errors {:?}; panics 0, hangs 0, NaN in Ok 0",
            self.cases,
            started.elapsed().as_secs_f64(),
            self.slowest.as_secs_f64(),
            self.ok,
            self.errors
        );
    }
}

/// Runs one case under the watchdog, turning a panic or a hang into a
/// failure and tallying the outcome (`fine`: no NaN in an `Ok`).
pub(crate) fn case(
    tally: &RefCell<Tally>,
    f: impl FnOnce() -> (bool, Vec<Result<(), String>>) + Send + 'static,
) -> Result<(), TestCaseError> {
    let started = Instant::now();
    let ended = watched(f);
    let mut t = tally.borrow_mut();
    t.cases += 1;
    t.slowest = t.slowest.max(started.elapsed());
    match ended {
        Ended::Hung => Err(TestCaseError::fail(format!("hung for {:?}", time_limit()))),
        Ended::Panicked(message) => Err(TestCaseError::fail(format!("panicked: {message}"))),
        Ended::Done((fine, outcomes)) => {
            if !fine {
                let lies: Vec<&String> = outcomes
                    .iter()
                    .filter_map(|o| o.as_ref().err())
                    .filter(|e| e.starts_with("NaN or ∞"))
                    .collect();
                return Err(TestCaseError::fail(format!("{lies:?}")));
            }
            for outcome in outcomes {
                match outcome {
                    Ok(()) => t.ok += 1,
                    Err(kind) => t.error(&kind),
                }
            }
            Ok(())
        }
    }
}

/// The outcome of one call: its `Ok` checked by `good`, its `Err` named.
pub(crate) fn outcome<T, E: std::fmt::Debug>(
    result: Result<T, E>,
    good: impl FnOnce(&T) -> bool,
    fine: &mut bool,
    outcomes: &mut Vec<Result<(), String>>,
) -> Option<T> {
    match result {
        Ok(value) => {
            if !good(&value) {
                *fine = false;
                outcomes.push(Err(format!(
                    "NaN or ∞ inside an Ok<{}>",
                    std::any::type_name::<T>()
                )));
            }
            outcomes.push(Ok(()));
            Some(value)
        }
        Err(e) => {
            outcomes.push(Err(format!("{e:?}")));
            None
        }
    }
}

/// The worksheet's four-bar with its midpoints, lengths scaled by `scale`
/// or replaced by awkward numbers.
pub(crate) fn four_bar(bits: &[u64; 4], ordinary: bool) -> FourBar {
    let l = |k: usize, usual: f64| {
        if ordinary { usual } else { awkward(bits[k]) }
    };
    FourBar {
        l1: l(0, 80.0),
        l2: l(1, 20.0),
        l3: l(2, 50.0),
        l4: l(3, 70.0),
    }
}
