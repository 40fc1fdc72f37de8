//! An offset slider-crank, written, analysed, swept with its dead centres
//! and extremes located, and drawn — by a crate whose only dependency is
//! linkage, with the crate docs alone.
//!
//!     cargo run -p own-crate     # prints the results, writes out/own_crate/slider_crank.svg

use linkage::draw::scene::{Frame, Scene};
use linkage::prelude::*;
use linkage::watch::{Axis, Found, Of, Watch, locate};
use std::f64::consts::TAU;

/// Crank OB of length r turning about O, rod BP of length l, the slider P
/// on a guide at height e above O.
#[linkage::linkage(
    u = [theta3, s],
    v = [theta2],
    points = [
        B = (r * theta2.cos(), r * theta2.sin()),
        P = (s, e),
    ],
    closure = [
        r * theta2.cos() + l * theta3.cos() - s,
        r * theta2.sin() + l * theta3.sin() - e,
    ],
)]
#[derive(Clone, Debug)]
struct OffsetSliderCrank {
    r: f64,
    l: f64,
    e: f64,
}

const CRANK: OffsetSliderCrank = OffsetSliderCrank {
    r: 0.05,
    l: 0.2,
    e: 0.01,
};
/// ω2 = 300 rpm
const OMEGA2: f64 = 300.0 * TAU / 60.0;

/// A revolution of the crank at ω2, from θ2 = 0.
fn revolution() -> Result<Sweep<2, 1>, linkage::Error> {
    let drive = Drive::Line {
        from: vector![0.0],
        to: vector![TAU],
        steps: 72,
    };
    let options = SweepOptions {
        speed: OMEGA2,
        ..SweepOptions::default()
    };
    CRANK.sweep(&vector![-0.05, 0.25], &drive, &options)
}

/// The dead centres (ṡ = 0) and the slider's peak accelerations.
fn extremes(sweep: &Sweep<2, 1>) -> Result<Vec<Found<2, 1>>, linkage::watch::WatchError> {
    let watches = [
        Watch::coordinate("s", Of::Velocity).zeros(),
        Watch::point("P", Axis::X, Of::Acceleration).extrema(),
    ];
    locate(&CRANK, sweep, &watches, &Options::default())
}

/// The pose drawn with its arrows and the slider's path over `sweep`.
fn drawing(
    pose: &Analysis<2, 1, [Vector2<f64>; 2]>,
    sweep: &Sweep<2, 1>,
) -> Result<String, linkage::draw::scene::SceneError> {
    let cycle: Vec<Frame> = sweep
        .poses
        .iter()
        .map(|p| Frame::from_sweep_pose(&CRANK, p))
        .collect();
    Scene::new()
        .ground("O", [0.0, 0.0])
        .link(["O", "B"])
        .link(["B", "P"])
        .slider("P", 0.0)
        .velocities(["B", "P"])
        .velocity_scale(0.02)
        .accelerations(["P"])
        .trace(["P"])
        .units("m", "s")
        .render(&Frame::from_analysis(&CRANK, pose), &cycle)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let pose = CRANK.analyze(
        &vector![-0.05, 0.25],
        &vector![30f64.to_radians()],
        &vector![OMEGA2],
        &vector![0.0],
        &Options::default(),
    )?;
    let p = OffsetSliderCrank::P;
    println!(
        "θ2 = 30°: s = {:.6} m, ṡ = {:.6} m/s, s̈ = {:.4} m/s²",
        pose.u[1], pose.point_velocities[p].x, pose.point_accelerations[p].x
    );
    let sweep = revolution()?;
    for f in extremes(&sweep)? {
        println!(
            "{:?} at θ2 = {:.10}°: s = {:.10} m, s̈ = {:.4} m/s²",
            f.kind,
            f.v[0].to_degrees(),
            f.u[1],
            f.uddot[1]
        );
    }
    let svg = drawing(&pose, &sweep)?;
    let folder = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../out/own_crate");
    std::fs::create_dir_all(&folder)?;
    let path = folder.join("slider_crank.svg");
    std::fs::write(&path, svg)?;
    println!("wrote {}", path.display());
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use linkage::watch::FoundKind;

    /// The dead centres at their closed forms: s = √((l ± r)² − e²) at
    /// θ2 = atan2(e, s) (+ π for the inner one).
    #[test]
    fn the_dead_centres_are_where_the_closed_forms_put_them() {
        let OffsetSliderCrank { r, l, e } = CRANK;
        let sweep = revolution().unwrap();
        let found = extremes(&sweep).unwrap();
        let dead: Vec<&Found<2, 1>> = found.iter().filter(|f| f.watch == 0).collect();
        assert_eq!(dead.len(), 2);
        for (f, (s, extra)) in dead
            .iter()
            .zip([(l + r, 0.0), (l - r, std::f64::consts::PI)])
        {
            let s = (s * s - e * e).sqrt();
            assert!((f.u[1] - s).abs() <= 1e-15, "{} against {s}", f.u[1]);
            assert!((f.v[0] - (e.atan2(s) + extra)).abs() <= 1e-14);
        }
        assert_eq!(dead[0].kind, FoundKind::Zero { rising: false });
        // The slider's peak accelerations, one each way, are extrema of s̈:
        // its rate along the drive is zero there to rounding of r·ω².
        let peaks: Vec<&Found<2, 1>> = found.iter().filter(|f| f.watch == 1).collect();
        assert_eq!(peaks.len(), 2, "{peaks:?}");
        for f in peaks {
            assert!(
                f.rate.abs() <= 1e-12 * r * OMEGA2.powi(2),
                "rate {}",
                f.rate
            );
        }
    }

    #[test]
    fn the_pose_is_drawn() {
        let pose = CRANK
            .analyze(
                &vector![-0.05, 0.25],
                &vector![1.0],
                &vector![OMEGA2],
                &vector![0.0],
                &Options::default(),
            )
            .unwrap();
        let svg = drawing(&pose, &revolution().unwrap()).unwrap();
        for id in ["slider-P", "velocity-P", "acceleration-P", "scale-bar"] {
            assert!(svg.contains(&format!("id=\"{id}")), "no {id}");
        }
    }
}
