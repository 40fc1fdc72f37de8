//! `Mechanism` for JavaScript: a loaded file and the analyses the page
//! asks of it — a pose with its vectors, a sweep of the drive range with
//! the points' paths and the singular poses met, the picture.

use linkage::draw::scene::{Frame, MarkerShape, Markers, Placement, SceneError};
use linkage::file::{DxfChoice, FixedDrives, Loaded};
use linkage::mechanism::Fixed;
use linkage::mechanism::sizes::{Job, PARAMETERS, SensitivityJob, SizeError, run, run_sensitive};
use linkage::prelude::*;
use serde_json::{Value, json};
use wasm_bindgen::prelude::*;

/// A mechanism made from a mechanism file's (or a topology's) text.
#[wasm_bindgen(js_name = Mechanism)]
pub struct WebMechanism {
    loaded: Loaded,
}

/// Why a call failed, as a JavaScript `Error` with the library's message.
fn failed(error: impl std::fmt::Display) -> JsError {
    JsError::new(&error.to_string())
}

/// Failures of the jobs, with their message.
pub(crate) struct Failure(pub(crate) String);

impl Failure {
    /// A failure with `error`'s message.
    pub(crate) fn of(error: impl std::fmt::Display) -> Failure {
        Failure(error.to_string())
    }
}

impl From<SizeError> for Failure {
    fn from(e: SizeError) -> Failure {
        Failure(e.to_string())
    }
}

impl From<linkage::file::LoadError> for Failure {
    fn from(e: linkage::file::LoadError) -> Failure {
        Failure(e.to_string())
    }
}

impl From<linkage::Error> for Failure {
    fn from(e: linkage::Error) -> Failure {
        Failure(e.to_string())
    }
}

fn xy(points: &[Vector2<f64>]) -> Vec<[f64; 2]> {
    points.iter().map(|p| [p.x, p.y]).collect()
}

fn drive_json<const F: usize>(d: &FixedDrives<F>) -> Value {
    json!({
        "at": d.at.as_slice(), "from": d.from.as_slice(), "to": d.to.as_slice(),
        "rate": d.rate.as_slice(), "acceleration": d.acceleration.as_slice(), "steps": d.steps,
    })
}

/// The pose at the drivers' values `v` (the file's `at` when empty), from
/// the file's assembly there, at the file's rates.
struct Pose<'a> {
    loaded: &'a Loaded,
    v: Vec<f64>,
}

impl Job for Pose<'_> {
    type Output = Value;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<Value, Failure> {
        let v = given(&self.v)?;
        let (drives, pose) = (self.loaded).analysed_at(&model, v)?;
        let v = v.unwrap_or(drives.at);
        Ok(json!({
            "v": v.as_slice(), "u": pose.u.as_slice(), "udot": pose.udot.as_slice(),
            "uddot": pose.uddot.as_slice(), "points": xy(pose.points.as_ref()),
            "pointVelocities": xy(pose.point_velocities.as_ref()),
            "pointAccelerations": xy(pose.point_accelerations.as_ref()),
            "rcond": pose.rcond, "drive": drive_json(&drives),
        }))
    }
}

/// The file's sweep in `steps` steps: every pose's drivers, coordinates
/// and points, and the singular poses met.
struct Poses<'a> {
    loaded: &'a Loaded,
    steps: usize,
}

impl Job for Poses<'_> {
    type Output = Value;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<Value, Failure> {
        let steps = if self.steps == 0 {
            self.loaded.drives(&model)?.steps
        } else {
            self.steps
        };
        let (mut v, mut u, mut points) = (Vec::<f64>::new(), Vec::<f64>::new(), Vec::<f64>::new());
        let (mut udot, mut uddot, mut transmission) =
            (Vec::<f64>::new(), Vec::<f64>::new(), Vec::<f64>::new());
        let summary = self.loaded.sweep_each(&model, steps, &mut |_, pose| {
            v.extend(pose.v.iter());
            u.extend(pose.u.iter());
            udot.extend(pose.udot.iter());
            uddot.extend(pose.uddot.iter());
            // The equivalent transmission angle (a four-bar's own).
            transmission.push(linkage::transmission::equivalent_angle(
                &model.psi_u(&pose.u, &pose.v),
            ));
            let p = model.point_positions(&pose.u, &pose.v);
            points.extend(p.as_ref().iter().flat_map(|q| [q.x, q.y]));
        })?;
        let events: Vec<Value> = (summary.events.iter())
            .map(|e| {
                let kind = match e.kind {
                    EventKind::LimitPosition => "limit position",
                    EventKind::BranchPoint => "branch point",
                };
                let at = model.point_positions(&e.u, &e.v);
                json!({ "kind": kind, "v": e.v.as_slice(), "u": e.u.as_slice(), "points": xy(at.as_ref()) })
            })
            .collect();
        Ok(json!({
            "v": v, "u": u, "udot": udot, "uddot": uddot, "transmission": transmission,
            "points": points, "events": events, "complete": summary.complete,
        }))
    }
}

/// The file's picture at the drivers' values `v` (its `at` if empty),
/// with the points' paths over the drive range, the poses where the sweep
/// meets a singular pose (a dead centre, a limit position) drawn faint
/// behind it, and `targets` marked and numbered; with where it puts the
/// model (for reading a click on it as a point).
struct Picture<'a> {
    loaded: &'a Loaded,
    width: f64,
    v: Vec<f64>,
    targets: &'a [[f64; 2]],
    /// Other poses to draw faint (the dead centres, found once for the
    /// mechanism's dimensions rather than at every redraw).
    dead_centres: &'a [GivenPose],
    arrows: Arrows,
}

/// Which points the picture draws arrows at.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Arrows {
    /// Those the file's drawing names.
    File,
    /// Those, and every point's velocity.
    Velocities,
    /// Those, and every point's velocity and acceleration.
    Both,
}

impl Arrows {
    fn named(name: &str) -> Option<Arrows> {
        match name {
            "file" => Some(Arrows::File),
            "velocities" => Some(Arrows::Velocities),
            "both" => Some(Arrows::Both),
            _ => None,
        }
    }
}

/// A pose given by the page: its coordinates and drivers.
#[derive(serde::Deserialize)]
struct GivenPose {
    u: Vec<f64>,
    v: Vec<f64>,
}

impl GivenPose {
    /// The pose's frame, if it has the mechanism's sizes and is finite.
    fn frame<const M: usize, const F: usize, const P: usize>(
        &self,
        model: &Fixed<M, F, P>,
    ) -> Result<Frame, Failure> {
        let finite = self.u.iter().chain(&self.v).all(|x| x.is_finite());
        if self.u.len() != M || self.v.len() != F || !finite {
            return Err(Failure(format!(
                "a pose drawn faint has {M} coordinates and {F} driver values, each finite"
            )));
        }
        let u = SVector::<f64, M>::from_fn(|k, _| self.u[k]);
        let v = SVector::<f64, F>::from_fn(|k, _| self.v[k]);
        Ok(Frame::positions(model, &u, &v))
    }
}

/// What the faint poses are, for the legend.
fn faint(dead_centres: bool, singular: bool) -> &'static str {
    match (dead_centres, singular) {
        (true, true) => "dead centres and singular poses, faint",
        (true, false) => "dead centres, faint",
        (false, true) => "singular poses, faint",
        (false, false) => "",
    }
}

impl Job for Picture<'_> {
    type Output = (String, Placement);
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<(String, Placement), Failure> {
        let (drives, pose) = (self.loaded).analysed_at(&model, given(&self.v)?)?;
        let frame = Frame::from_analysis(&model, &pose);
        let mut cycle = Vec::new();
        let summary = self.loaded.sweep_each(&model, drives.steps, &mut |_, p| {
            cycle.push(Frame::from_sweep_pose(&model, p))
        })?;
        let singular: Vec<Frame> = (summary.events.iter())
            .map(|e| Frame::positions(&model, &e.u, &e.v))
            .collect();
        let dead_centres = (self.dead_centres.iter())
            .map(|pose| pose.frame(&model))
            .collect::<Result<Vec<Frame>, Failure>>()?;
        let mut scene = (self.loaded)
            .scene_of(&model)
            .width(self.width)
            .ghosts(&dead_centres)
            .ghosts(&singular)
            .ghost_name(faint(!dead_centres.is_empty(), !singular.is_empty()));
        let points = model.point_names();
        if self.arrows != Arrows::File {
            scene = scene.velocities(points);
        }
        if self.arrows == Arrows::Both {
            scene = scene.accelerations(points);
        }
        if !self.targets.is_empty() {
            scene = scene.markers(
                Markers::new("targets", self.targets.iter().copied())
                    .shape(MarkerShape::Circle)
                    .colour("#c0392b")
                    .numbered(),
            );
        }
        let drawn = |e: SceneError| Failure(format!("the drawing: {e}"));
        let placement = scene.placement(&frame, &cycle).map_err(drawn)?;
        let svg = scene.render(&frame, &cycle).map_err(drawn)?;
        Ok((svg, placement))
    }
}

/// The sensitivities of the pose at the drivers' values `v` (the file's
/// `at` if empty): each coordinate's and each point's derivative by each
/// parameter the mechanism is differentiated by (at most
/// [`PARAMETERS`]), the drivers held.
struct Differentiate<'a> {
    loaded: &'a Loaded,
    v: Vec<f64>,
}

impl SensitivityJob for Differentiate<'_> {
    type Output = Value;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P, PARAMETERS>,
    ) -> Result<Value, Failure> {
        let (_, pose) = (self.loaded).analysed_at(&model, given(&self.v)?)?;
        let s = model.sensitivities_of(&pose, &Options::default())?;
        let names: Vec<&str> = (model.param_names().into_iter())
            .filter(|n| !n.is_empty())
            .collect();
        let k = names.len();
        // u_p row by row; each point's (x, y) by each parameter.
        let u_p: Vec<Vec<f64>> = (0..M)
            .map(|i| (0..k).map(|j| s.u[(i, j)]).collect())
            .collect();
        let points = model.point_names().len();
        let points_p: Vec<Vec<[f64; 2]>> = (0..points)
            .map(|c| {
                (0..k)
                    .map(|j| {
                        let d = s.points[j].as_ref()[c];
                        [d.x, d.y]
                    })
                    .collect()
            })
            .collect();
        Ok(json!({ "parameters": names, "u": u_p, "points": points_p, "rcond": s.rcond }))
    }
}

/// The drivers `v` given (one per driver, finite), or none (the drive's
/// `at`) if `v` is empty.
fn given<const F: usize>(v: &[f64]) -> Result<Option<SVector<f64, F>>, Failure> {
    if v.is_empty() {
        Ok(None)
    } else if v.len() == F && v.iter().all(|x| x.is_finite()) {
        Ok(Some(SVector::from_fn(|k, _| v[k])))
    } else {
        Err(Failure(format!(
            "{} driver values for {F} drivers, each finite",
            v.len()
        )))
    }
}

/// The dead centres over the file's drive range: what comes to rest, and
/// the pose there with its points.
struct DeadCentres<'a> {
    loaded: &'a Loaded,
}

impl Job for DeadCentres<'_> {
    type Output = Value;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<Value, Failure> {
        let found = self.loaded.dead_centres(&model).map_err(Failure::of)?;
        Ok(found
            .iter()
            .map(|d| {
                let at = model.point_positions(&d.u, &d.v);
                json!({ "what": d.what, "v": d.v.as_slice(), "u": d.u.as_slice(), "points": xy(at.as_ref()) })
            })
            .collect())
    }
}

/// The file's mechanism as DXF.
struct Dxf<'a> {
    loaded: &'a Loaded,
    choice: DxfChoice,
}

impl Job for Dxf<'_> {
    type Output = String;
    type Error = Failure;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<String, Failure> {
        self.loaded.dxf(&model, &self.choice).map_err(Failure::of)
    }
}

#[wasm_bindgen(js_class = Mechanism)]
impl WebMechanism {
    /// The mechanism of a mechanism file's (or a topology's) text, called
    /// `name` in messages; its mistakes, all of them, in the error's
    /// message (see `mistakes` for their places).
    #[wasm_bindgen(js_name = fromText)]
    pub fn from_text(text: &str, name: &str) -> Result<WebMechanism, JsError> {
        Ok(WebMechanism {
            loaded: Loaded::from_text(name, text).map_err(failed)?,
        })
    }

    /// Its names and parameters, as JSON.
    pub fn info(&self) -> String {
        let m = self.loaded.mechanism();
        json!({
            "name": m.name(), "uNames": m.u_names(), "vNames": m.v_names(),
            "pointNames": m.point_names(), "parameterNames": m.parameter_names(),
            "parameters": m.parameters(), "lengthUnit": self.loaded.file().length_unit,
            "fileArrows": self.loaded.file().drawing.as_ref()
                .map_or(0, |d| d.velocities.len() + d.accelerations.len()),
        })
        .to_string()
    }

    /// Sets a parameter.
    #[wasm_bindgen(js_name = setParameter)]
    pub fn set_parameter(&mut self, name: &str, value: f64) -> Result<(), JsError> {
        self.loaded
            .mechanism_mut()
            .set_parameter(name, value)
            .map_err(failed)
    }

    /// The pose at the drivers' values `v` (the file's `at` if empty), as
    /// JSON.
    pub fn analyze(&self, v: Vec<f64>) -> Result<String, JsError> {
        let job = Pose {
            loaded: &self.loaded,
            v,
        };
        let pose = run(self.loaded.mechanism(), job).map_err(|Failure(why)| JsError::new(&why))?;
        Ok(pose.to_string())
    }

    /// The file's sweep in `steps` steps (the file's own when 0), as JSON.
    pub fn sweep(&self, steps: usize) -> Result<String, JsError> {
        if steps > linkage::file::MOST_STEPS {
            return Err(JsError::new(&format!(
                "a sweep takes 1 to {} steps",
                linkage::file::MOST_STEPS
            )));
        }
        let job = Poses {
            loaded: &self.loaded,
            steps,
        };
        let swept = run(self.loaded.mechanism(), job).map_err(|Failure(why)| JsError::new(&why))?;
        Ok(swept.to_string())
    }

    /// The mechanism drawn with its drivers at `v` (the file's `at` if
    /// empty), `width` pixels wide, with its points' paths and its
    /// singular poses: SVG.
    pub fn svg(&self, width: f64, v: Vec<f64>) -> Result<String, JsError> {
        self.picture_of(width, v, &[], &[], Arrows::File)
            .map(|(svg, _)| svg)
    }

    /// Where a link pinned to the frame or a block on a fixed guide comes
    /// to rest over the drive range (from the file's drawing), as JSON
    /// `[{what, v, u, points}]`, in the order of the sweep.
    #[wasm_bindgen(js_name = deadCentres)]
    pub fn dead_centres(&self) -> Result<String, JsError> {
        let job = DeadCentres {
            loaded: &self.loaded,
        };
        let found = run(self.loaded.mechanism(), job).map_err(|Failure(why)| JsError::new(&why))?;
        Ok(found.to_string())
    }

    /// [`WebMechanism::svg`] with the points `targets` (JSON `[[x, y],
    /// …]`) marked and numbered, the poses `dead_centres` (JSON `[{u, v},
    /// …]`, as [`WebMechanism::dead_centres`] gives them) drawn faint,
    /// arrows at the points the file names (`arrows` "file"), or at every
    /// point too ("velocities", "both": velocities and accelerations), and
    /// where the picture puts the model:
    /// JSON `{svg, placement: {scale, origin: [x, y], top, width,
    /// height}}` (a pixel (px, py) is the model point (origin.x + px /
    /// scale, origin.y − (py − top) / scale)).
    pub fn picture(
        &self,
        width: f64,
        v: Vec<f64>,
        targets: &str,
        dead_centres: &str,
        arrows: &str,
    ) -> Result<String, JsError> {
        let arrows = Arrows::named(arrows)
            .ok_or_else(|| JsError::new("the arrows are \"file\", \"velocities\" or \"both\""))?;
        let targets: Vec<[f64; 2]> = serde_json::from_str(targets).map_err(|_| {
            JsError::new("the targets are a list of points [x, y] of finite numbers")
        })?;
        if targets.iter().flatten().any(|x| !x.is_finite()) {
            return Err(JsError::new("a target is not finite"));
        }
        let dead_centres: Vec<GivenPose> = serde_json::from_str(dead_centres)
            .map_err(|_| JsError::new("the poses drawn faint are a list of {u, v}"))?;
        let (svg, placed) = self.picture_of(width, v, &targets, &dead_centres, arrows)?;
        Ok(json!({
            "svg": svg,
            "placement": {
                "scale": placed.scale, "origin": [placed.origin.x, placed.origin.y],
                "top": placed.top, "width": placed.width, "height": placed.height,
            },
        })
        .to_string())
    }

    /// The mechanism for CAD, as DXF: its pose at the drive's `at` (each
    /// link an outline with pin holes, a layer each, the traced paths), or
    /// with `cut_sheet` its moving links laid flat; a mechanism given by
    /// joints and links only.
    pub fn dxf(&self, cut_sheet: bool) -> Result<String, JsError> {
        let job = Dxf {
            loaded: &self.loaded,
            choice: DxfChoice {
                cut_sheet,
                ..DxfChoice::default()
            },
        };
        run(self.loaded.mechanism(), job).map_err(|Failure(why)| JsError::new(&why))
    }

    /// The sensitivities of the pose at the drivers' values `v` (the
    /// file's `at` if empty), as JSON `{parameters, u: [[∂uᵢ/∂pⱼ]], points:
    /// [[[∂x/∂pⱼ, ∂y/∂pⱼ]]], rcond}`: exact, from the equations'
    /// derivatives.
    pub fn sensitivities(&self, v: Vec<f64>) -> Result<String, JsError> {
        let job = Differentiate {
            loaded: &self.loaded,
            v,
        };
        // By every parameter it is differentiated by (more than
        // PARAMETERS of them is an error that says so).
        let found = run_sensitive(self.loaded.mechanism(), &[], job)
            .map_err(|Failure(why)| JsError::new(&why))?;
        Ok(found.to_string())
    }

    fn picture_of(
        &self,
        width: f64,
        v: Vec<f64>,
        targets: &[[f64; 2]],
        dead_centres: &[GivenPose],
        arrows: Arrows,
    ) -> Result<(String, Placement), JsError> {
        if !(width.is_finite() && width > 0.0 && width <= 100_000.0) {
            return Err(JsError::new(
                "the width is a number of pixels from 0 to 100000",
            ));
        }
        let job = Picture {
            loaded: &self.loaded,
            width,
            v,
            targets,
            dead_centres,
            arrows,
        };
        run(self.loaded.mechanism(), job).map_err(|Failure(why)| JsError::new(&why))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const FOUR_BAR: &str = include_str!("../../mechanisms/four_bar.toml");

    /// The four-bar's two dead centres, found once, are drawn faint and
    /// named in the legend; a pose of the wrong size is refused, saying
    /// why.
    #[test]
    fn dead_centres_are_drawn_faint_and_named() {
        let loaded = Loaded::from_text("four_bar.toml", FOUR_BAR).ok().unwrap();
        let found = run(loaded.mechanism(), DeadCentres { loaded: &loaded })
            .ok()
            .unwrap();
        let found = found.as_array().unwrap();
        let at: Vec<f64> = found.iter().map(|d| d["v"][0].as_f64().unwrap()).collect();
        assert_eq!(found[0]["what"], "C–D");
        assert!((at[0] - (4.0f64 / 7.0).acos()).abs() < 2e-15, "{at:?}");
        assert!((at[1] - 240f64.to_radians()).abs() < 2e-15, "{at:?}");
        let poses: Vec<GivenPose> = serde_json::from_value(Value::from(found.clone())).unwrap();
        let picture = |dead_centres: &[GivenPose]| {
            let job = Picture {
                loaded: &loaded,
                width: 640.0,
                v: Vec::new(),
                targets: &[],
                dead_centres,
                arrows: Arrows::File,
            };
            run(loaded.mechanism(), job)
        };
        let (svg, _) = picture(&poses).ok().unwrap();
        assert_eq!(svg.matches(r#"class="ghost""#).count(), 2);
        assert!(svg.contains("dead centres, faint"));
        let (plain, _) = picture(&[]).ok().unwrap();
        assert!(!plain.contains(r#"class="ghost""#) && !plain.contains("faint"));
        let wrong = [GivenPose {
            u: vec![0.0],
            v: vec![0.0],
        }];
        match picture(&wrong) {
            Err(Failure(why)) => {
                assert!(why.contains("2 coordinates and 1 driver values"), "{why}")
            }
            Ok(_) => panic!("a pose of one coordinate drawn for a four-bar"),
        }
    }

    /// A mechanism given by joints and links names no arrow: asked for,
    /// every point's velocity (and acceleration) is drawn.
    #[test]
    fn every_points_arrows_on_request() {
        let text = include_str!("../../mechanisms/joints/four_bar.toml");
        let loaded = Loaded::from_topology("four_bar.toml", text).ok().unwrap().1;
        let arrows = |arrows: Arrows| {
            let job = Picture {
                loaded: &loaded,
                width: 640.0,
                v: Vec::new(),
                targets: &[],
                dead_centres: &[],
                arrows,
            };
            let (svg, _) = run(loaded.mechanism(), job).ok().unwrap();
            let count = |kind: &str| svg.matches(&format!(r#"class="arrow {kind}""#)).count();
            (count("velocity"), count("acceleration"))
        };
        let points = loaded.mechanism().point_names().len();
        assert_eq!(arrows(Arrows::File), (0, 0));
        assert_eq!(arrows(Arrows::Velocities), (points, 0));
        assert_eq!(arrows(Arrows::Both), (points, points));
        assert_eq!(Arrows::named("sideways"), None);
    }
}
