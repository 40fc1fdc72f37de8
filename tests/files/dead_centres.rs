//! The dead centres of the library's files, checked from the outside: the
//! slider-crank's against its closed form, and at every dead centre of
//! every file the point that comes to rest at rest (its velocity zero to
//! rounding beside its fastest over the cycle: 1e-13 of it; the worst
//! of these files is 1.5e-15).

use linkage::file::{DeadCentre, Loaded};
use linkage::mechanism::Fixed;
use linkage::mechanism::sizes::{Job, SizeError, run};
use linkage::prelude::*;

fn loaded(path: &str) -> Loaded {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(path);
    Loaded::read(&path).unwrap_or_else(|e| panic!("{e}"))
}

/// The slider-crank's slider at rest where the crank and the rod are in
/// line: stretched out, P at √((l + r)² − e²) with the crank at
/// atan2(e, that); folded, P at √((l − r)² − e²), the crank opposite.
/// Found to the bit; held to 1e-15.
#[test]
fn the_slider_crank_stops_where_its_crank_and_rod_are_in_line() {
    let file = loaded("mechanisms/slider_crank.toml");
    let crank = file.mechanism().fixed::<2, 1>().unwrap();
    let found = file.dead_centres(&crank).unwrap();
    // In metres: the model reads every length in SI units.
    let (r, l, e) = (0.05_f64, 0.2_f64, 0.01_f64);
    let outer = ((l + r).powi(2) - e * e).sqrt();
    let inner = ((l - r).powi(2) - e * e).sqrt();
    let expected = [
        (e.atan2(outer), outer),
        (e.atan2(inner) + std::f64::consts::PI, inner),
    ];
    assert_eq!(found.len(), 2, "{found:?}");
    for (dead, (theta2, s)) in found.iter().zip(expected) {
        assert_eq!(dead.what, "P");
        assert!(
            (dead.v[0] - theta2).abs() < 1e-15,
            "{dead:?} against {theta2}"
        );
        assert!((dead.u[1] - s).abs() < 1e-15, "{dead:?} against {s}");
    }
}

/// Each dead centre's resting point (named first in `what`) and its
/// speed there, beside its fastest over the sweep.
struct AtRest<'a> {
    loaded: &'a Loaded,
}

impl Job for AtRest<'_> {
    type Output = Vec<(String, f64, f64)>;
    type Error = SizeError;
    fn run<const M: usize, const F: usize, const P: usize>(
        self,
        model: Fixed<M, F, P>,
    ) -> Result<Self::Output, SizeError> {
        let found: Vec<DeadCentre<M, F>> = self.loaded.dead_centres(&model).unwrap();
        let drives = self.loaded.drives(&model).unwrap();
        let names = model.point_names();
        let speed = |name: &str, u: &SVector<f64, M>, v: &SVector<f64, F>| {
            let pose = model
                .analyze(
                    u,
                    v,
                    &drives.rate,
                    &drives.acceleration,
                    &Options::default(),
                )
                .unwrap();
            let k = names.iter().position(|n| *n == name).unwrap();
            pose.point_velocities.as_ref()[k].norm()
        };
        let mut poses = Vec::new();
        self.loaded
            .sweep_each(&model, drives.steps, &mut |_, pose| {
                poses.push((pose.u, pose.v));
            })
            .unwrap();
        Ok(found
            .iter()
            .map(|dead| {
                let point = dead.what.split('–').next().unwrap();
                let peak = (poses.iter())
                    .map(|(u, v)| speed(point, u, v))
                    .fold(0.0, f64::max);
                (dead.what.clone(), speed(point, &dead.u, &dead.v), peak)
            })
            .collect())
    }
}

#[test]
fn at_every_dead_centre_its_point_is_at_rest() {
    let mut seen = Vec::new();
    for path in [
        "mechanisms/four_bar.toml",
        "mechanisms/slider_crank.toml",
        "mechanisms/six_bar.toml",
        "mechanisms/quick_return.toml",
        "mechanisms/shaper.toml",
        "mechanisms/jansen_leg.toml",
        "mechanisms/joints/four_bar.toml",
        "mechanisms/joints/quick_return.toml",
    ] {
        let file = loaded(path);
        let job = AtRest { loaded: &file };
        for (what, speed, peak) in run(file.mechanism(), job).unwrap() {
            assert!(peak > 0.0, "{path}: {what} never moves");
            assert!(
                speed <= 1e-13 * peak,
                "{path}: {what} at {speed} against {peak} at most"
            );
            seen.push(format!("{path}: {what}"));
        }
    }
    // Rockers and sliders of several kinds were found.
    for what in [
        "mechanisms/four_bar.toml: C–D",
        "mechanisms/six_bar.toml: F–G",
        "mechanisms/quick_return.toml: R",
        "mechanisms/quick_return.toml: P–C",
    ] {
        assert!(seen.iter().any(|s| s == what), "{what} in {seen:?}");
    }
}

/// A file without `[drawing]` has no bodies to come to rest.
#[test]
fn a_file_without_a_drawing_has_no_dead_centre() {
    let text = "name = \"Crank\"\nequations = '''\nu = [x], v = [t],\npoints = [P = (x, t)],\nclosure = [x - t.sin()],\n'''\n[drive.t]\nfrom = 0\nto = 6\nsteps = 60\n";
    let file = Loaded::from_text("crank.toml", text).unwrap();
    let model = file.mechanism().fixed::<1, 1>().unwrap();
    assert_eq!(file.dead_centres(&model).unwrap(), Vec::new());
}

/// A topology's pivot is its parameters: moved after the file was read
/// (as the page's drag moves it), its links turn about it where it now is
/// — the picture draws it there, and the rocker rests there.
#[test]
fn a_moved_pivot_is_where_the_rocker_turns() {
    let mut file = loaded("mechanisms/joints/four_bar.toml");
    let before = {
        let bar = file.mechanism().fixed::<2, 1>().unwrap();
        file.dead_centres(&bar).unwrap()
    };
    let mechanism = file.mechanism_mut();
    mechanism.set_parameter("x_D", 85.0).unwrap();
    mechanism.set_parameter("y_D", 4.0).unwrap();
    let bar = file.mechanism().fixed::<2, 1>().unwrap();
    let pivots = file.pivots(&bar);
    assert!(
        pivots.contains(&("D".to_owned(), [85.0, 4.0])),
        "{pivots:?}"
    );
    assert!(pivots.contains(&("A".to_owned(), [0.0, 0.0])), "{pivots:?}");
    let after = file.dead_centres(&bar).unwrap();
    assert_eq!((before.len(), after.len()), (2, 2));
    assert!((after[0].v[0] - before[0].v[0]).abs() > 1e-3);
    let job = AtRest { loaded: &file };
    for (what, speed, peak) in run(file.mechanism(), job).unwrap() {
        assert!(speed <= 1e-13 * peak, "{what} at {speed} against {peak}");
    }
    // Drawn where it now is.
    let written = file.file().scene_of(bar.point_names());
    assert_eq!(file.scene_of(&bar), written.ground("D", [85.0, 4.0]));
}
