//! Our side of each task: `synthesize`, timed, and the evaluation rate of
//! the residuals with their exact Jacobian.

use linkage::mechanisms::CouplerFourBar;
use linkage::synthesis::{
    Candidate, Problem, Requirements, Search, Synthesis, SynthesisError, synthesize,
};
use linkage::{Options, Sensitivities};
use std::time::Instant;

/// Random starts of a path run: chosen when 64 left stream 1 without a
/// design for either path task; with the certificate's 40° transmission
/// angle the first-design runs take up to 72 starts through 5 points
/// (stream 4), so 64 would not do for every stream.
pub const PATH_STARTS: usize = 128;
/// The random streams of the path runs (one run each).
pub const STREAMS: u64 = 5;
/// The most starts a run to the first certified design may take.
pub const FIRST_STARTS: usize = 1024;
/// Random starts of a function run.
pub const FUNCTION_STARTS: usize = 16;
/// Runs of the function task (one stream: they differ only in time).
pub const FUNCTION_RUNS: usize = 21;
/// The budgets of the convergence runs: 16, 32, … 1024 starts.
pub const LADDER: [usize; 7] = [16, 32, 64, 128, 256, 512, 1024];

/// One run of `synthesize`.
pub struct Run<L> {
    pub seconds: f64,
    pub synthesis: Synthesis<L, 2>,
}

impl<L> Run<L> {
    pub fn designs(&self) -> &[Candidate<L, 2>] {
        &self.synthesis.designs
    }
}

/// Timings of each path run (the same run: its result does not change),
/// of which the median is kept, on this shared machine.
pub const REPEATS: usize = 3;

/// `synthesize` from the stream `stream` with `search`'s starts, timed
/// `repeats` times: the last run, with the median of the times.
pub fn run_median<L, const K: usize>(
    problem: &Problem<L, 2, K>,
    requirements: &Requirements<'_, L, 2>,
    search: &Search,
    repeats: usize,
) -> Result<Run<L>, SynthesisError>
where
    L: Sensitivities<2, 1, K> + Clone + Sync + Send,
{
    let mut seconds = Vec::new();
    let mut last = None;
    for _ in 0..repeats.max(1) {
        let found = timed(problem, requirements, search)?;
        seconds.push(found.seconds);
        last = Some(found);
    }
    let mut found = last.expect("at least one run");
    found.seconds = crate::results::median(&seconds);
    Ok(found)
}

/// The search of `starts` starts from the stream `stream`.
pub fn every(starts: usize, stream: u64) -> Search {
    Search {
        starts,
        random_state: stream,
        ..Search::default()
    }
}

/// The search from the stream `stream` that stops with the round of
/// starts that certifies a design.
pub fn first(stream: u64) -> Search {
    Search {
        enough: Some(1),
        ..every(FIRST_STARTS, stream)
    }
}

/// `synthesize` with `starts` starts from the stream `stream`, timed.
pub fn run<L, const K: usize>(
    problem: &Problem<L, 2, K>,
    requirements: &Requirements<'_, L, 2>,
    starts: usize,
    stream: u64,
) -> Result<Run<L>, SynthesisError>
where
    L: Sensitivities<2, 1, K> + Clone + Sync + Send,
{
    timed(problem, requirements, &every(starts, stream))
}

/// `synthesize` with `search`, timed.
fn timed<L, const K: usize>(
    problem: &Problem<L, 2, K>,
    requirements: &Requirements<'_, L, 2>,
    search: &Search,
) -> Result<Run<L>, SynthesisError>
where
    L: Sensitivities<2, 1, K> + Clone + Sync + Send,
{
    let time = Instant::now();
    let synthesis = synthesize(problem, requirements, search)?;
    Ok(Run {
        seconds: time.elapsed().as_secs_f64(),
        synthesis,
    })
}

/// Evaluations per second, on one core, of the residuals and their exact
/// Jacobian of `problem` near the design `design` (its unknowns moved by
/// up to 1e-4 of their bounds' widths, as a solver's trials are, each
/// solved from the design's poses), over about a second; the rate, and how
/// many evaluations it counted.
pub fn rate(
    problem: &Problem<CouplerFourBar, 2, 9>,
    design: &Candidate<CouplerFourBar, 2>,
    widths: &[f64],
) -> (f64, usize) {
    let params = design.model.params();
    let mut x: Vec<f64> = params.iter().copied().collect();
    x.extend(&design.drivers);
    let options = Options::default();
    let mut trial = x.clone();
    let (mut count, mut failed) = (0usize, 0usize);
    let time = Instant::now();
    while time.elapsed().as_secs_f64() < 1.0 {
        for _ in 0..100 {
            for (i, t) in trial.iter_mut().enumerate() {
                let width = widths.get(i).copied().unwrap_or(1.0);
                *t = x[i] + 1e-4 * width * ((count * 7 + i * 13) as f64).sin();
            }
            match problem.evaluate(&trial, &design.poses, &options) {
                Some(found) => {
                    std::hint::black_box(found);
                }
                None => failed += 1,
            }
            count += 1;
        }
    }
    assert_eq!(failed, 0, "the trials near a design evaluate");
    (count as f64 / time.elapsed().as_secs_f64(), count)
}
