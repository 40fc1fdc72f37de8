//! Fuzzing what the library reads at run time: mechanism texts
//! (`Mechanism::from_text`, the attribute's grammar), mechanism files
//! (`MechanismFile::parse`, then the file's mechanism) and topologies
//! (topology files, pyslvs's expressions, pylinkage's JSON: `topologies`), built from the 13
//! files of `mechanisms/` and from the grammar — token swaps, deletions,
//! duplications, awkward numbers (huge, tiny, not finite, long runs of
//! digits), deep nesting, long inputs, unicode and control characters,
//! values with unknown or misplaced units, paths as values, keys deleted,
//! renamed and invented, drives that do not assemble, parameters missing,
//! unknown, not finite.
//!
//! Each case is run as a user runs a file: read, made into its mechanism,
//! then (when it is one of the sizes compiled here) assembled at the
//! drivers' `at` as the file picks, analysed there at the drivers' rates,
//! carried back to `from`, swept over the drive, and its drawing
//! rendered. The sweeps are short — 24 steps, each of at most 2 000
//! sub-steps — so that a case's time is the library's, not the work a
//! file asks for (a drive of 10⁵ turns is a sweep of millions of
//! sub-steps, not a fault: here it ends in `SubstepLimit`). The
//! properties, for every case:
//!
//! - it ends (a watchdog: no hang), and within a second in a release
//!   build (counted and reported);
//! - it does not panic;
//! - an `Ok` holds no NaN or ∞ (the assembly, the analysis, every pose
//!   and event of the sweeps, the numbers written into the SVG);
//! - every error is typed, and every mistake of the text or file is
//!   located: a byte range inside the text, on character boundaries, as
//!   are its labels, and it renders; no `Internal` error.
//!
//! Every case is made from its own random generator, started from the
//! campaign's constant and the case's index: `LINKAGE_CASE=k` runs case k
//! alone and prints its input (the whole of it into the file
//! `LINKAGE_CASE_FILE`, if set). The number of cases per campaign is
//! `LINKAGE_CASES` (default 150, what CI runs); the long run:
//!
//!     LINKAGE_CASES=100000 cargo test --release --test reliability files:: -- --nocapture --test-threads 1

mod corpus;
mod generate;
mod mutate;
mod random;
mod regressions;
mod run;
mod topologies;

use crate::watchdog::{Ended, watched};
use random::Rng;
use run::{Report, TextCase};
use std::collections::BTreeMap;
use std::time::{Duration, Instant};

fn cases() -> u64 {
    std::env::var("LINKAGE_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(150)
}

/// The case to run alone, if one is asked for.
fn only() -> Option<u64> {
    std::env::var("LINKAGE_CASE")
        .ok()
        .and_then(|s| s.parse().ok())
}

/// A case slower than this is reported as slow.
const SLOW: Duration = Duration::from_secs(1);

/// What a campaign found.
#[derive(Default)]
struct Tally {
    kinds: BTreeMap<String, usize>,
    times: Vec<Duration>,
    panics: Vec<String>,
    hangs: Vec<String>,
    lies: Vec<String>,
    unlocated: Vec<String>,
    internal: Vec<String>,
    slow: Vec<(u64, Duration, String)>,
}

impl Tally {
    fn record(&mut self, index: u64, elapsed: Duration, ended: Ended<Report>) {
        self.times.push(elapsed);
        if elapsed > SLOW {
            let kind = match &ended {
                Ended::Done(report) => report.kind.clone(),
                Ended::Panicked(_) => "panicked".into(),
                Ended::Hung => "hung".into(),
            };
            self.slow.push((index, elapsed, kind));
        }
        match ended {
            Ended::Hung => {
                self.hangs.push(format!("case {index}"));
                *self.kinds.entry("hung".into()).or_default() += 1;
            }
            Ended::Panicked(message) => {
                self.panics.push(format!("case {index}: {message}"));
                *self.kinds.entry("panicked".into()).or_default() += 1;
            }
            Ended::Done(report) => {
                let Report {
                    kind,
                    lies,
                    unlocated,
                    internal,
                } = report;
                let at =
                    |what: Vec<String>| what.into_iter().map(move |w| format!("case {index}: {w}"));
                self.lies.extend(at(lies));
                self.unlocated.extend(at(unlocated));
                self.internal.extend(at(internal));
                *self.kinds.entry(kind).or_default() += 1;
            }
        }
    }

    /// Prints what was found — the table's row (campaign, cases, `Ok`,
    /// typed errors, panics, hangs — cases over a second, or past the
    /// watchdog —, NaN in `Ok`,
    /// errors without a place, internal errors, median and slowest case),
    /// the outcomes by stage and kind — and fails if anything broke a
    /// property.
    fn report(mut self, name: &str, started: Instant) {
        self.times.sort();
        let n = self.times.len();
        let median = self.times.get(n / 2).copied().unwrap_or_default();
        let max = self.times.last().copied().unwrap_or_default();
        let count = |f: &dyn Fn(&str) -> bool| -> usize {
            (self.kinds.iter())
                .filter(|(k, _)| f(k))
                .map(|(_, n)| n)
                .sum()
        };
        let ok = count(&|k| k.starts_with("Ok"));
        let errors = count(&|k| !k.starts_with("Ok") && k != "panicked" && k != "hung");
        eprintln!(
            "| {name} | {n} | {ok} | {errors} | {} | {} | {} | {} | {} | {:.2} ms | {:.0} ms | ({} slower than 1 s)",
            self.panics.len(),
            self.hangs.len(),
            self.lies.len(),
            self.unlocated.len(),
            self.internal.len(),
            median.as_secs_f64() * 1e3,
            max.as_secs_f64() * 1e3,
            self.slow.len(),
        );
        let mut stages: BTreeMap<&str, usize> = BTreeMap::new();
        for (kind, k) in &self.kinds {
            *stages
                .entry(kind.split(':').next().unwrap_or(kind))
                .or_default() += k;
        }
        eprintln!("    by stage: {stages:?}");
        eprintln!("    ({:.1} s in all)", started.elapsed().as_secs_f64());
        let mut kinds: Vec<(String, usize)> = self.kinds.into_iter().collect();
        kinds.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
        for (kind, count) in &kinds {
            eprintln!("    {count:>8}  {kind}");
        }
        // The slowest 20, slowest first.
        self.slow.sort_by_key(|s| std::cmp::Reverse(s.1));
        for (index, t, kind) in self.slow.iter().take(20) {
            eprintln!("    slow: case {index}, {:.2} s, {kind}", t.as_secs_f64());
        }
        let mut broken = Vec::new();
        for (what, list) in [
            ("panics", &self.panics),
            ("hangs", &self.hangs),
            ("NaN or ∞ in Ok", &self.lies),
            ("errors without a place", &self.unlocated),
            ("internal errors", &self.internal),
        ] {
            if !list.is_empty() {
                broken.push(format!(
                    "{} {what}: {:#?}",
                    list.len(),
                    &list[..list.len().min(20)]
                ));
            }
        }
        assert!(broken.is_empty(), "{name}: {}", broken.join("\n"));
    }
}

/// Runs a campaign: each case made by `make` from its generator, run by
/// `run` under the watchdog.
fn campaign<C: Send + std::fmt::Debug + 'static>(
    name: &str,
    campaign_constant: u64,
    make: impl Fn(&mut Rng) -> C,
    run: fn(&C) -> Report,
) {
    let started = Instant::now();
    let mut tally = Tally::default();
    let indices: Vec<u64> = match only() {
        Some(k) => vec![k],
        None => (0..cases()).collect(),
    };
    let mut making = Duration::ZERO;
    for index in indices {
        let t = Instant::now();
        let input = make(&mut Rng::for_case(campaign_constant, index));
        making += t.elapsed();
        if only().is_some() {
            let shown = format!("{input:#?}");
            let cut = (0..=shown.len().min(4000))
                .rev()
                .find(|&k| shown.is_char_boundary(k))
                .unwrap_or(0);
            eprintln!(
                "case {index} ({} bytes shown of {}): {}",
                cut,
                shown.len(),
                &shown[..cut]
            );
            // The whole input, to reproduce it elsewhere.
            if let Some(path) = std::env::var_os("LINKAGE_CASE_FILE") {
                std::fs::write(path, &shown).expect("the case's file");
            }
        }
        let t = Instant::now();
        let ended = watched(move || run(&input));
        tally.record(index, t.elapsed(), ended);
    }
    eprintln!("    ({:.1} s making the cases)", making.as_secs_f64());
    tally.report(name, started);
}

impl std::fmt::Debug for TextCase {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(f, "name {:?}, parameters {:?}", self.name, self.parameters)?;
        writeln!(f, "at {:?}, to {:?}", self.at, self.to)?;
        write!(f, "{}", self.text)
    }
}

/// A text case: the equations of a library file, mutated, with its
/// parameters (now and then one missing, unknown, misnamed or not
/// finite); or made up from the grammar; or token soup.
fn text_input(rng: &mut Rng) -> TextCase {
    let (text, mut parameters) = match rng.below(20) {
        0..=8 => {
            let (_, file) = rng.pick(corpus::LIBRARY);
            let (_, equations) = corpus::equations(file);
            (mutate::mutate_few(rng, equations), corpus::parameters(file))
        }
        9 | 10 => {
            let (_, file) = rng.pick(corpus::LIBRARY);
            let (_, equations) = corpus::equations(file);
            let mut parameters = corpus::parameters(file);
            for p in parameters.iter_mut() {
                if rng.one_in(3) {
                    p.1 = generate::value(rng);
                }
            }
            (equations.to_string(), parameters)
        }
        11..=18 => {
            let made = generate::mechanism(rng);
            let parameters = (made.parameters.iter())
                .map(|p| (p.clone(), generate::value(rng)))
                .collect();
            let text = if rng.one_in(4) {
                mutate::mutate_few(rng, &made.text)
            } else {
                made.text
            };
            (text, parameters)
        }
        _ => {
            let mut soup = String::new();
            for _ in 0..rng.between(0, 64) {
                soup = mutate::capped(mutate::mutate(rng, &soup));
            }
            (soup, Vec::new())
        }
    };
    if !parameters.is_empty() && rng.one_in(10) {
        let k = rng.below(parameters.len());
        parameters.remove(k);
    }
    if rng.one_in(10) {
        parameters.push(("zz".into(), 1.0));
    }
    if !parameters.is_empty() && rng.one_in(20) {
        let copy = rng.pick(&parameters).clone();
        parameters.push(copy);
    }
    if !parameters.is_empty() && rng.one_in(30) {
        let k = rng.below(parameters.len());
        parameters[k].0 = rng
            .pick(&["", "1x", "self", "θ", "l1 ", "u", "r#type", "a-b", "x"])
            .to_string();
    }
    let name = if rng.one_in(20) {
        rng.pick(&[
            "", "1Bar", "self", "Self", "θBar", "Four Bar", "r#type", "fn", "_",
        ])
        .to_string()
    } else if rng.one_in(50) {
        "N".repeat(rng.between(100, 70_000))
    } else {
        "Fuzz".to_string()
    };
    let at: Vec<f64> = (0..3).map(|_| (rng.unit() * 2.0 - 1.0) * 3.0).collect();
    let to: Vec<f64> = at
        .iter()
        .map(|a| a + (rng.unit() * 2.0 - 1.0) * 6.0)
        .collect();
    TextCase {
        name,
        text,
        parameters,
        at,
        to,
    }
}

/// A file case: a library file mutated, or with its numbers nudged, or a
/// file made up.
fn file_input(rng: &mut Rng) -> String {
    match rng.below(10) {
        0..=4 => corpus::mutated_file(rng),
        5 | 6 => corpus::nudged_file(rng),
        _ => corpus::made_file(rng),
    }
}

fn run_text(case: &TextCase) -> Report {
    run::text_case(case)
}

// The campaign hands each case to its runner as `&C`, here `&String`.
#[allow(clippy::ptr_arg)]
fn run_file(text: &String) -> Report {
    run::file_case(text)
}

#[test]
fn mechanism_texts_never_hang_panic_or_lie() {
    campaign("mechanism texts", 0x7465_7874_7331, text_input, run_text);
}

#[test]
fn topologies_never_hang_panic_or_lie() {
    campaign(
        "topologies",
        0x746f_706f_6c31,
        topologies::input,
        topologies::run,
    );
}

#[test]
fn mechanism_files_never_hang_panic_or_lie() {
    campaign("mechanism files", 0x6669_6c65_7331, file_input, run_file);
}

/// Every file of the library, as it is, goes the whole way: the
/// campaign's analyses reach the end on them.
#[test]
fn the_library_goes_the_whole_way() {
    for (name, text) in corpus::LIBRARY {
        let report = run::file_case(text);
        assert_eq!(report.kind, "Ok: the whole sweep", "{name}: {report:?}");
        assert!(report.lies.is_empty(), "{name}: {report:?}");
    }
}
