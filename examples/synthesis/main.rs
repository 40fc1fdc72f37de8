//! Synthesis side by side with pylinkage 1.3.0: the same tasks, judged by
//! the same certificate.
//!
//! 1. Path generation without prescribed timing: a four-bar's coupler
//!    point through 5 and through 9 points of the Maple worksheet's coupler
//!    curve of G3, taken at evenly spaced crank angles (so an exact
//!    solution exists), every one of the nine dimensions free.
//! 2. Function generation: Freudenstein's three precision points for
//!    y = log10 x on 1 ≤ x ≤ 10 (Chebyshev spacing), the crank from 0° to
//!    60°, the rocker from 90° to 180°; ours must match the closed form to
//!    1e-12.
//!
//! Every design — ours and, with `--peers FILE`, pylinkage's from the file
//! `benches/peers/synthesis.sh` writes — is judged the same way: its error
//! at the targets on its own swept curve, and `synthesis::certify` over the
//! range from the poses where it meets them (branch and order defects,
//! singular poses, designs that do not assemble). Also the evaluation rate
//! of our residuals with their exact Jacobian (the 9-point problem) against
//! pylinkage's objective.
//!
//! Writes to `out/synthesis/` (or where `LINKAGE_OUT` says):
//! `targets.svg`, `designs.svg`, `convergence.svg` and `designs.csv` (every
//! design: dimensions, error, verdict).
//!
//!     cargo run --release --example synthesis
//!     benches/peers/synthesis.sh     # pylinkage, then this with --peers

mod charts;
mod judge;
mod ours;
mod peers;
mod results;
mod tasks;

#[path = "../support/output.rs"]
mod output;

use linkage::mechanisms::{CouplerFourBar, FourBar};
use linkage::prelude::*;
use linkage::synthesis::{Candidate, Range, Requirements};
use results::{Design, Method, Run, median};
use std::error::Error;
use tasks::FunctionTask;

/// The file named by `--peers`, if given.
fn peers_argument() -> Result<Option<String>, String> {
    let mut args = std::env::args().skip(1);
    match (args.next().as_deref(), args.next(), args.next()) {
        (None, _, _) => Ok(None),
        (Some("--peers"), Some(file), None) => Ok(Some(file)),
        _ => Err("usage: synthesis [--peers benches/results/synthesis_pylinkage.csv]".to_owned()),
    }
}

/// A convergence curve: (wall time, error) of the best design so far.
pub struct Series {
    pub task: String,
    pub label: String,
    pub points: Vec<(f64, f64)>,
    /// Drawn as a line (a run's trace) or as markers only (separate runs).
    pub line: bool,
}

fn main() -> Result<(), Box<dyn Error>> {
    let peers = match peers_argument()? {
        Some(file) => Some(peers::parse(&std::fs::read_to_string(&file)?)?),
        None => None,
    };
    let folder = output::folder("synthesis")?;
    let mut methods = Vec::new();
    let mut series = Vec::new();

    methods.extend(function(peers.as_deref())?);
    let mut drawn = Vec::new();
    let mut nine = None;
    for n in [5, 9] {
        let targets = tasks::path_targets(n)?;
        let (found, curves, best) = path(n, &targets, peers.as_deref())?;
        methods.extend(found);
        series.extend(curves);
        drawn.push(targets);
        nine = best;
    }
    let nine = nine.ok_or("no design through the 9 points")?;

    println!("## Synthesis side by side with pylinkage\n");
    println!("{}", results::table(&methods));
    if peers.is_some() {
        println!("{}", speed_ups(&methods));
    }
    println!("{}", rates(&nine, peers.as_deref())?);

    std::fs::write(folder.join("designs.csv"), results::csv(&methods))?;
    std::fs::write(folder.join("targets.svg"), charts::targets(&drawn)?)?;
    std::fs::write(
        folder.join("designs.svg"),
        charts::designs(&methods, &drawn)?,
    )?;
    std::fs::write(
        folder.join("convergence.svg"),
        charts::convergence(&series)?,
    )?;
    eprintln!("written to {}", folder.display());
    Ok(())
}

/// Freudenstein's task: ours (checked against the closed form) and
/// pylinkage's `function_generation`.
fn function(peers: Option<&[peers::Row]>) -> Result<Vec<Method>, Box<dyn Error>> {
    let task = FunctionTask::log10();
    let closed = task
        .closed_form()
        .ok_or("the three points are degenerate")?;
    println!(
        "Freudenstein's closed form for y = log10 x: crank {:.15}, coupler {:.15}, rocker {:.15} (ground 1)",
        closed[0], closed[1], closed[2]
    );
    let off = |l: [f64; 3]| (0..3).map(|i| (l[i] - closed[i]).abs()).fold(0.0, f64::max);
    let problem = task.problem()?;
    let requirements = FunctionTask::requirements();
    let mut runs = Vec::new();
    for index in 0..ours::FUNCTION_RUNS {
        let run = ours::run(&problem, &requirements, ours::FUNCTION_STARTS, 1)?;
        let designs = run
            .designs()
            .iter()
            .map(|d| {
                let m = &d.model;
                let gap = off([m.l2, m.l3, m.l4]);
                if gap > 1e-12 {
                    return Err(format!("ours is {gap:.1e} from the closed form: {m:?}"));
                }
                Ok(function_design(m, &d.poses[0], &task))
            })
            .collect::<Result<Vec<_>, _>>()?;
        if designs.is_empty() {
            return Err("no design for Freudenstein's task".into());
        }
        runs.push(Run {
            index,
            seconds: run.seconds,
            designs,
        });
    }
    let gap = runs[0]
        .designs
        .iter()
        .map(|d| d.params.iter().skip(1).map(|p| p.1).collect::<Vec<_>>())
        .map(|l| off([l[0], l[1], l[2]]))
        .fold(0.0, f64::max);
    println!("ours from the closed form: {gap:.1e} at most");
    let mut methods = vec![Method {
        task: "function".to_owned(),
        tool: "linkage",
        name: "synthesize".to_owned(),
        setting: format!("{} starts", ours::FUNCTION_STARTS),
        runs,
    }];
    if let Some(rows) = peers {
        check_targets(rows, "function", &task.targets.map(|t| vector![t.0, t.1]))?;
        for name in peers::methods(rows, "function", &["design", "none"]) {
            let mut run = Run {
                index: 0,
                seconds: f64::NAN,
                designs: Vec::new(),
            };
            for row in rows
                .iter()
                .filter(|r| r.task == "function" && r.method == name)
            {
                run.seconds = row.seconds;
                if row.record == "design" {
                    let (model, u, _) = row.four_bar()?;
                    println!(
                        "pylinkage from the closed form: {:.1e}",
                        off([
                            model.l2 / model.l1,
                            model.l3 / model.l1,
                            model.l4 / model.l1
                        ])
                    );
                    run.designs.push(function_design(&model, &u, &task));
                }
            }
            methods.push(Method {
                task: "function".to_owned(),
                tool: "pylinkage",
                name: name.to_owned(),
                setting: "one call (median of 5 × 200)".to_owned(),
                runs: vec![run],
            });
        }
    }
    Ok(methods)
}

fn function_design(model: &FourBar, u: &SVector<f64, 2>, task: &FunctionTask) -> Design {
    Design {
        params: vec![
            ("l1", model.l1),
            ("l2", model.l2),
            ("l3", model.l3),
            ("l4", model.l4),
        ],
        judged: judge::function(model, u, task),
        drawn: None,
    }
}

fn path_design(
    model: &CouplerFourBar,
    u: &SVector<f64, 2>,
    v: f64,
    targets: &[Vector2<f64>],
) -> Design {
    let params = CouplerFourBar::PARAM_NAMES
        .iter()
        .copied()
        .zip(model.params().iter().copied())
        .collect();
    Design {
        params,
        judged: judge::path(model, u, v, targets),
        drawn: Some((*model, *u, v)),
    }
}

/// A path task's methods, convergence curves, and our first design.
type PathFound = (
    Vec<Method>,
    Vec<Series>,
    Option<Candidate<CouplerFourBar, 2>>,
);

/// The path task through `targets`: ours over several streams, a ladder
/// of budgets for the convergence, and pylinkage's methods.
fn path(
    n: usize,
    targets: &[Vector2<f64>],
    peers: Option<&[peers::Row]>,
) -> Result<PathFound, Box<dyn Error>> {
    let task = format!("path{n}");
    let names: Vec<&str> = tasks::path_bounds(targets).iter().map(|b| b.0).collect();
    assert_eq!(
        names,
        CouplerFourBar::PARAM_NAMES,
        "every dimension free, in order"
    );
    let problem = tasks::path_problem(targets)?;
    let requirements = Requirements::new(Range::Revolution);
    let judged = |run: &ours::Run<CouplerFourBar>, index: usize| Run {
        index,
        seconds: run.seconds,
        designs: run
            .designs()
            .iter()
            .map(|d| path_design(&d.model, &d.poses[0], d.drivers[0], targets))
            .collect(),
    };
    let (mut runs, mut firsts) = (Vec::new(), Vec::new());
    let mut best = None;
    let mut first_starts = Vec::new();
    for stream in 1..=ours::STREAMS {
        let every = ours::every(ours::PATH_STARTS, stream);
        let run = ours::run_median(&problem, &requirements, &every, ours::REPEATS)?;
        runs.push(judged(&run, stream as usize));
        if best.is_none() {
            best = run.designs().first().cloned();
        }
        let first = ours::run_median(&problem, &requirements, &ours::first(stream), ours::REPEATS)?;
        first_starts.push(first.synthesis.starts.to_string());
        firsts.push(judged(&first, stream as usize));
    }
    let first_points: Vec<(f64, f64)> = firsts
        .iter()
        .filter_map(|r| Some((r.seconds, r.best()?.judged.error())))
        .collect();
    let mut methods = vec![
        Method {
            task: task.clone(),
            tool: "linkage",
            name: "synthesize, every design".to_owned(),
            setting: format!(
                "{} starts, one stream each (median of {} timings)",
                ours::PATH_STARTS,
                ours::REPEATS
            ),
            runs,
        },
        Method {
            task: task.clone(),
            tool: "linkage",
            name: "synthesize, first design".to_owned(),
            setting: format!(
                "starts in order until one design is certified ({} starts), one stream each (median of {} timings)",
                first_starts.join(", "),
                ours::REPEATS
            ),
            runs: firsts,
        },
    ];
    // The ladder of budgets; its largest run's designs, every one judged,
    // are a row of their own.
    let mut ladder = Vec::new();
    let mut first = None;
    let mut largest = None;
    for starts in ours::LADDER {
        let run = judged(&ours::run(&problem, &requirements, starts, 1)?, 1);
        if let Some(best) = run.best() {
            ladder.push((run.seconds, best.judged.error()));
            first.get_or_insert(starts);
        }
        largest = Some(run);
    }
    methods.push(Method {
        task: task.clone(),
        tool: "linkage",
        name: "synthesize".to_owned(),
        setting: format!("{} starts, stream 1", ours::LADDER[ours::LADDER.len() - 1]),
        runs: largest.into_iter().collect(),
    });
    let mut series = vec![Series {
        task: task.clone(),
        label: format!(
            "linkage: synthesize, {}…{} starts, a run each ({})",
            ours::LADDER[0],
            ours::LADDER[ours::LADDER.len() - 1],
            match first {
                Some(starts) if starts > ours::LADDER[0] => {
                    format!("designs from {starts} on")
                }
                Some(_) => "designs from every one".to_owned(),
                None => "no design".to_owned(),
            }
        ),
        points: ladder,
        line: true,
    }];
    series.push(Series {
        task: task.clone(),
        label: format!(
            "linkage: synthesize to the first certified design, streams 1–{}",
            ours::STREAMS
        ),
        points: first_points,
        line: false,
    });
    if let Some(rows) = peers {
        check_targets(rows, &task, targets)?;
        for name in peers::methods(rows, &task, &["design", "none"]) {
            let mut found: Vec<Run> = Vec::new();
            for row in rows.iter().filter(|r| {
                r.task == task && r.method == name && (r.record == "design" || r.record == "none")
            }) {
                let run = match found.iter().position(|r| r.index == row.run) {
                    Some(i) => &mut found[i],
                    None => {
                        found.push(Run {
                            index: row.run,
                            seconds: row.seconds,
                            designs: Vec::new(),
                        });
                        found.last_mut().expect("pushed")
                    }
                };
                if row.record == "design" {
                    let (model, u, v) = row.coupler_four_bar();
                    run.designs.push(path_design(&model, &u, v, targets));
                }
            }
            let setting = if name.starts_with("Burmester") {
                "`path_generation`: its orientation grid until max_solutions designs verify"
            } else if name.starts_with("PSO") {
                "100 particles × 200 iterations (its defaults), then Nelder–Mead (≤ 4000 iterations)"
            } else {
                "population 15 × 9, ≤ 300 generations, SciPy's polish; random stream = run"
            };
            if name.starts_with("Burmester") {
                let points: Vec<(f64, f64)> = found
                    .iter()
                    .filter_map(|r| Some((r.seconds, r.best()?.judged.error())))
                    .collect();
                let label = if points.is_empty() {
                    let seconds: Vec<String> =
                        found.iter().map(|r| results::time(r.seconds)).collect();
                    format!("pylinkage: {name}: no design, after {}", seconds.join(", "))
                } else {
                    format!("pylinkage: {name}")
                };
                series.push(Series {
                    task: task.clone(),
                    label,
                    points,
                    line: false,
                });
            }
            methods.push(Method {
                task: task.clone(),
                tool: "pylinkage",
                name: name.to_owned(),
                setting: setting.to_owned(),
                runs: found,
            });
        }
        for name in peers::methods(rows, &task, &["trace"]) {
            let runs: Vec<usize> = {
                let mut r: Vec<usize> = rows
                    .iter()
                    .filter(|r| r.task == task && r.method == name && r.record == "trace")
                    .map(|r| r.run)
                    .collect();
                r.dedup();
                r
            };
            for run in runs {
                let trace: Vec<&peers::Row> = rows
                    .iter()
                    .filter(|r| {
                        r.task == task && r.method == name && r.record == "trace" && r.run == run
                    })
                    .collect();
                let errors = linkage::batch::map(&trace, |r| {
                    let (model, u, v) = r.coupler_four_bar();
                    judge::path_error(&model, &u, v, targets)
                });
                let points = trace
                    .iter()
                    .zip(errors)
                    .filter_map(|(r, e)| Some((r.seconds, e?)))
                    .collect();
                series.push(Series {
                    task: task.clone(),
                    label: format!("pylinkage: {name}, run {run}"),
                    points,
                    line: true,
                });
            }
        }
    }
    Ok((methods, series, best))
}

/// The file's targets must be ours.
fn check_targets(rows: &[peers::Row], task: &str, targets: &[Vector2<f64>]) -> Result<(), String> {
    let theirs: Vec<(f64, f64)> = rows
        .iter()
        .filter(|r| r.task == task && r.record == "target")
        .map(peers::Row::target)
        .collect();
    let same = theirs.len() == targets.len()
        && theirs
            .iter()
            .zip(targets)
            .all(|(a, b)| (a.0 - b.x).abs() < 1e-9 && (a.1 - b.y).abs() < 1e-9);
    if same {
        Ok(())
    } else {
        Err(format!(
            "pylinkage's {task} targets {theirs:?} are not ours {targets:?}"
        ))
    }
}

/// How much faster ours is on each task than each of pylinkage's methods,
/// median against median, with the errors they reach (below 1: pylinkage
/// is faster).
fn speed_ups(methods: &[Method]) -> String {
    let mut t = String::from(
        "| task | pylinkage: method | its median time | its median error | ours: method | median time | median error | pylinkage's time / ours |\n|---|---|---:|---:|---|---:|---:|---:|\n",
    );
    // Ours: the methods of several runs (a median), not the ladder's.
    for ours in methods
        .iter()
        .filter(|m| m.tool == "linkage" && m.runs.len() > 1)
    {
        for theirs in methods
            .iter()
            .filter(|m| m.tool == "pylinkage" && m.task == ours.task)
        {
            let (a, b) = (median(&theirs.seconds()), median(&ours.seconds()));
            let ratio = if a / b >= 10.0 {
                format!("{:.0}", a / b)
            } else {
                format!("{:.2}", a / b)
            };
            t.push_str(&format!(
                "| {} | {} | {} | {} | {} | {} | {} | {ratio}× |\n",
                results::task_name(&ours.task),
                theirs.name,
                results::time(a),
                results::error(&ours.task, median(&theirs.best_errors())),
                ours.name,
                results::time(b),
                results::error(&ours.task, median(&ours.best_errors())),
            ));
        }
    }
    t
}

/// Evaluations per second, one core: our residuals with their exact
/// Jacobian (18 × 18) on the 9-point problem against pylinkage's objective
/// on the same task.
fn rates(
    design: &Candidate<CouplerFourBar, 2>,
    peers: Option<&[peers::Row]>,
) -> Result<String, Box<dyn Error>> {
    let targets = tasks::path_targets(9)?;
    let problem = tasks::path_problem(&targets)?;
    let widths: Vec<f64> = tasks::path_bounds(&targets)
        .iter()
        .map(|b| b.2 - b.1)
        .collect();
    let mut measured: Vec<f64> = (0..3)
        .map(|_| ours::rate(&problem, design, &widths).0)
        .collect();
    measured.sort_by(f64::total_cmp);
    let mut t = String::from(
        "| objective (9-point path task) | evaluations / s, one core (median of 3) |\n|---|---:|\n",
    );
    t.push_str(&format!(
        "| linkage: residuals and exact Jacobian (18 × 18), `Problem::evaluate` | {:.0} |\n",
        measured[1]
    ));
    if let Some(rows) = peers {
        for name in peers::methods(rows, "path9", &["rate"]) {
            let rates: Vec<f64> = rows
                .iter()
                .filter(|r| r.task == "path9" && r.record == "rate" && r.method == name)
                .map(|r| r.evaluations / r.seconds)
                .collect();
            t.push_str(&format!(
                "| pylinkage: the value alone, {name} | {:.0} |\n",
                median(&rates)
            ));
        }
    }
    Ok(t)
}
