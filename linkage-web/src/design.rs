//! `Design` for JavaScript: a path synthesis on the page's mechanism,
//! searched piece by piece — each call runs the starts that follow and
//! puts their certified designs after those found before
//! ([`Designing::absorb`]) — so that the page's worker reports progress
//! and can be stopped between pieces (a page's WebAssembly has one
//! thread: nothing reaches a call under way), and the designs of the pieces are those
//! of the whole search run at once.

use crate::mechanism::Failure;
use linkage::file::Loaded;
use linkage::mechanism::design::{DesignTask, DesignView, Designing, NoDesign, Targets};
use linkage::mechanism::sizes::{DesignJob, run_design};
use linkage::synthesis::{Search, Synthesis, Timing};
use serde_json::{Value, json};
use std::any::Any;
use wasm_bindgen::prelude::*;

/// A path synthesis on a mechanism file's mechanism, under way.
#[wasm_bindgen(js_name = Design)]
pub struct WebDesign {
    loaded: Loaded,
    task: DesignTask,
    /// The random state of the starts.
    seed: u64,
    /// The problem posed and the designs found so far, at the
    /// mechanism's sizes (a `Designing<M, P>` and its `Synthesis`).
    state: Option<Box<dyn Any>>,
    /// The starts run so far.
    done: usize,
}

/// The problem posed at the mechanism's sizes and what its pieces found.
struct Under<const M: usize, const P: usize> {
    designing: Designing<M, P>,
    found: Synthesis<DesignView<M, P>, M>,
}

/// A piece of the search: the `count` starts from `first`.
struct Piece<'a> {
    loaded: &'a Loaded,
    task: &'a DesignTask,
    state: &'a mut Option<Box<dyn Any>>,
    search: Search,
}

impl DesignJob for Piece<'_> {
    type Output = Value;
    type Error = Failure;
    fn run<const M: usize, const P: usize>(
        self,
        model: DesignView<M, P>,
    ) -> Result<Value, Failure> {
        let fresh = !matches!(self.state, Some(s) if s.is::<Under<M, P>>());
        if fresh {
            let drives = self.loaded.drives(&model)?;
            let guess = self.loaded.assembled(&model, &drives.at)?;
            let designing = Designing::new(&model, Some(guess), self.task).map_err(Failure::of)?;
            let found = Synthesis {
                designs: Vec::new(),
                refused: Vec::new(),
                failed_starts: 0,
                starts: 0,
            };
            *self.state = Some(Box::new(Under { designing, found }));
        }
        let under = (self.state.as_mut())
            .and_then(|s| s.downcast_mut::<Under<M, P>>())
            .ok_or_else(|| Failure("the search's state is of another mechanism".into()))?;
        let piece = (under.designing)
            .search(&self.search, &|| {}, &|| false)
            .map_err(Failure::of)?;
        under.designing.absorb(&mut under.found, piece);
        Ok(report(&model, &under.found))
    }
}

/// The designs found so far, best first, as JSON: each one's parameters
/// (every parameter of the mechanism), its drivers at the targets, its
/// misses, and its certificate.
fn report<const M: usize, const P: usize>(
    model: &DesignView<M, P>,
    found: &Synthesis<DesignView<M, P>, M>,
) -> Value {
    let names = model.parameter_names();
    let designs: Vec<Value> = (found.designs.iter())
        .map(|d| {
            let values = d.model.parameters();
            let parameters: serde_json::Map<String, Value> = (names.iter())
                .zip(values.iter())
                .map(|(n, v)| (n.to_string(), json!(v)))
                .collect();
            let (worst, largest) = d.largest_error();
            let certificate = d.certificate.map(|c| {
                json!({
                    "from": c.from, "to": c.to,
                    "transmission": c.transmission.to_degrees(),
                    "transmissionAt": c.transmission_at,
                })
            });
            json!({
                "start": d.start, "parameters": parameters, "drivers": d.drivers,
                "errors": d.errors, "rmsError": d.rms_error,
                "largestError": largest, "worstTarget": worst,
                "certificate": certificate,
            })
        })
        .collect();
    // Without a design, why: the closest candidate and what it missed.
    let why = NoDesign::of(found).map(|none| none.to_string());
    json!({
        "designs": designs, "starts": found.starts, "refused": found.refused.len(),
        "failedStarts": found.failed_starts, "why": why,
    })
}

/// The task's JSON: `{point, targets: [[x, y], …], free: [[name, lower,
/// upper], …], seed, minTransmission}` (the angle in degrees; optional).
fn task_of(json: &str) -> Result<(DesignTask, u64), String> {
    let value: Value =
        serde_json::from_str(json).map_err(|e| format!("the task is not JSON: {e}"))?;
    let point = (value.get("point").and_then(Value::as_str))
        .ok_or("the task names its `point`")?
        .to_owned();
    let pair = |v: &Value| -> Option<[f64; 2]> {
        let p = v.as_array()?;
        Some([p.first()?.as_f64()?, p.get(1)?.as_f64()?])
    };
    let points: Vec<[f64; 2]> = (value.get("targets").and_then(Value::as_array))
        .and_then(|t| t.iter().map(pair).collect())
        .ok_or("the targets are a list of points [x, y]")?;
    let free: Vec<(String, f64, f64)> = (value.get("free").and_then(Value::as_array))
        .and_then(|f| {
            f.iter()
                .map(|e| {
                    let e = e.as_array()?;
                    Some((
                        e.first()?.as_str()?.to_owned(),
                        e.get(1)?.as_f64()?,
                        e.get(2)?.as_f64()?,
                    ))
                })
                .collect()
        })
        .ok_or("the free parameters are a list of [name, lower, upper]")?;
    let seed = value.get("seed").and_then(Value::as_u64).unwrap_or(1);
    let min_transmission = match value.get("minTransmission") {
        None | Some(Value::Null) => None,
        Some(angle) => Some(
            angle
                .as_f64()
                .ok_or("the smallest transmission angle is a number of degrees")?
                .to_radians(),
        ),
    };
    let task = DesignTask {
        targets: Targets::Path {
            point,
            points,
            timing: Timing::Free,
        },
        free,
        precision_points: true,
        min_transmission,
    };
    Ok((task, seed))
}

#[wasm_bindgen(js_class = Design)]
impl WebDesign {
    /// A path synthesis on the mechanism of the file's `text` (its
    /// assembly at the drive's `at` the starting design's): the task's
    /// JSON: `{point, targets: [[x, y], …], free: [[name, lower, upper], …], seed, minTransmission}` (the angle in degrees; optional). Certified designs only, through the
    /// targets (precision points), over a revolution of the driver.
    #[wasm_bindgen(constructor)]
    pub fn new(text: &str, task: &str) -> Result<WebDesign, JsError> {
        WebDesign::posed(text, task).map_err(|Failure(why)| JsError::new(&why))
    }

    /// Runs the next `count` starts (1 to 1024) and returns every design
    /// found so far, best first: each with its parameters, drivers, misses and certificate.
    pub fn next(&mut self, count: usize) -> Result<String, JsError> {
        (self.piece(count))
            .map(|found| found.to_string())
            .map_err(|Failure(why)| JsError::new(&why))
    }

    /// The starts run so far.
    pub fn done(&self) -> usize {
        self.done
    }
}

impl WebDesign {
    fn posed(text: &str, task: &str) -> Result<WebDesign, Failure> {
        let loaded = Loaded::from_text("the editor", text).map_err(Failure::of)?;
        let (task, seed) = task_of(task).map_err(Failure)?;
        Ok(WebDesign {
            loaded,
            task,
            seed,
            state: None,
            done: 0,
        })
    }

    fn piece(&mut self, count: usize) -> Result<Value, Failure> {
        if !(1..=1024).contains(&count) {
            return Err(Failure(format!("a piece is 1 to 1024 starts, not {count}")));
        }
        let names: Vec<&str> = self.task.free.iter().map(|(n, _, _)| n.as_str()).collect();
        let job = Piece {
            loaded: &self.loaded,
            task: &self.task,
            state: &mut self.state,
            search: Search {
                starts: count,
                first: self.done,
                random_state: self.seed,
                ..Search::default()
            },
        };
        let found = run_design(self.loaded.mechanism(), &names, job)?;
        self.done += count;
        Ok(found)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use linkage::prelude::*;

    const FOUR_BAR: &str = include_str!("../../mechanisms/four_bar.toml");

    /// G3 of the file's own four-bar at θ2 = 0°, 72°, … 288°: targets a
    /// design reaches exactly (the file's lengths among them).
    fn targets() -> Vec<[f64; 2]> {
        let loaded = Loaded::from_text("four_bar.toml", FOUR_BAR).ok().unwrap();
        let model = loaded.mechanism().fixed::<2, 1>().ok().unwrap();
        let g3 = model.point_names().iter().position(|&n| n == "G3").unwrap();
        (0..5)
            .map(|k| {
                let v = SVector::from([(72.0 * k as f64).to_radians()]);
                let u = loaded.assembled(&model, &v).ok().unwrap();
                let p = model.point_positions(&u, &v).as_ref()[g3];
                [p.x, p.y]
            })
            .collect()
    }

    fn task() -> String {
        json!({
            "point": "G3", "targets": targets(), "seed": 3,
            "free": [["l1", 40.0, 120.0], ["l2", 5.0, 40.0], ["l3", 20.0, 80.0], ["l4", 30.0, 110.0]],
        })
        .to_string()
    }

    /// Pieces of 4 starts give, piece after piece, the designs of one
    /// piece of 12: the search the page runs in a worker is the whole
    /// search. Its designs pass through the targets and are certified.
    #[test]
    fn pieces_are_the_whole_search() {
        let mut whole = WebDesign::posed(FOUR_BAR, &task()).ok().unwrap();
        let all = whole.piece(12).ok().unwrap();
        let mut pieces = WebDesign::posed(FOUR_BAR, &task()).ok().unwrap();
        let mut last = Value::Null;
        for _ in 0..3 {
            last = pieces.piece(4).ok().unwrap();
        }
        assert_eq!(last, all);
        let designs = all["designs"].as_array().unwrap();
        assert!(!designs.is_empty(), "{all}");
        for d in designs {
            assert!(d["largestError"].as_f64().unwrap() < 1e-6, "{d}");
            assert!(
                d["certificate"]["transmission"].as_f64().unwrap() >= 40.0,
                "{d}"
            );
        }
    }

    /// A task that cannot be read says why; a free parameter the
    /// mechanism lacks is the library's error.
    #[test]
    fn a_bad_task_says_why() {
        let why = |task: &str| match WebDesign::posed(FOUR_BAR, task) {
            Err(Failure(why)) => why,
            Ok(mut design) => match design.piece(1) {
                Err(Failure(why)) => why,
                Ok(found) => panic!("{task}: {found}"),
            },
        };
        assert!(why("{").contains("not JSON"));
        assert!(why(r#"{"point": "G3", "targets": [[0, "a"]], "free": []}"#).contains("targets"));
        let unknown = r#"{"point": "G3", "targets": [[0, 1]], "free": [["l9", 0, 1]]}"#;
        assert!(why(unknown).contains("l9"), "{}", why(unknown));
        assert!(
            why(&task().replace("\"seed\":3", "\"minTransmission\":\"x\"")).contains("degrees")
        );
    }
}
