//! The cam of the Mathcad course project: the tool-feed cam of
//! the shaping machine, an oscillating roller follower. Its phases come
//! from the shaper's motion (the crank angles where the ram is at 5 % of
//! its stroke), its law is the course project's piecewise-constant acceleration with
//! k = 1, and its size the course project read off a drawing: here the course project's design
//! is checked — its return stroke exceeds the pressure-angle limit — and
//! the smallest cam that keeps within the limit is found numerically.
//!
//! Writes to `out/cam/`: `cam.svg` (the cam at its worst pressure angle),
//! `motion.svg`, `pressure.svg` and `profile.csv` (the profile and the pitch
//! curve in millimetres, as the course project's x.txt and y.txt).
//!
//!     cargo run --release --example cam

#[path = "shaper/machine.rs"]
mod machine;
#[path = "support/output.rs"]
mod output;

use linkage::cam::{Cam, CamError, Follower, Law, Program, Rotation, Segment, smallest_rocker};
use linkage::draw::diagrams::{Chart, Panel};
use std::collections::HashMap;
use std::f64::consts::{FRAC_PI_2, PI};
use std::fmt::Write as _;

fn reference() -> HashMap<String, (f64, String)> {
    include_str!("../tests/data/shaper_cam_reference.csv")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("key,"))
        .map(|l| {
            let cols: Vec<&str> = l.split(',').collect();
            (
                cols[0].to_string(),
                (cols[1].parse().unwrap_or(f64::NAN), cols[2].to_string()),
            )
        })
        .collect()
}

fn heading(title: &str) {
    println!("\n{title}\n{}", "─".repeat(title.chars().count()));
    println!(
        "{:<34} {:>20}  {:>9}  {:>9}",
        "", "ours", "printed", "vs exact"
    );
}

/// The root of g in [a, b] by bisection.
fn bisect(g: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let ga = g(a);
    for _ in 0..100 {
        let m = 0.5 * (a + b);
        if (g(m) > 0.0) == (ga > 0.0) {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let reference = reference();
    let row = |label: &str, key: &str, ours: f64, note: &str| {
        let (exact, printed) = reference
            .get(&format!("cam.{key}"))
            .cloned()
            .unwrap_or((f64::NAN, String::new()));
        let vs = if exact.is_nan() {
            "—".to_string()
        } else if exact == 0.0 {
            format!("{:.1e}", ours.abs())
        } else {
            format!("{:.1e}", ((ours - exact) / exact).abs())
        };
        let printed = if printed.is_empty() {
            "—".to_string()
        } else {
            printed
        };
        println!("{label:<34} {ours:>20.12}  {printed:>9}  {vs:>9}  {note}");
    };
    let deg = |x: f64| x.to_degrees();
    let rad = |x: f64| x.to_radians();

    // 1. The phases, from the shaper's motion.
    let data = machine::COURSE_PROJECT;
    let shaper = machine::synthesize(&data)?;
    let m = machine::machine(&shaper, &data)?;
    let x0 = m.analysis(0.0)?.u[2];
    let travel = |phi: f64| {
        m.analysis(phi)
            .map(|a| a.u[2] - x0 - 0.05 * data.stroke)
            .unwrap_or(f64::NAN)
    };
    let f_p1 = bisect(travel, 0.1, 1.0);
    let f_p2 = bisect(travel, -1.0, -0.1);
    let ff_rab = PI + shaper.beta();
    println!("The cam of the shaping machine, by linkage");
    heading("1. Phase angles from the shaper's motion [°]");
    row(
        "f_p1: ram at 0.05 H, working stroke",
        "f_p1_deg",
        deg(f_p1),
        "",
    );
    row("f_p2: ram at 0.05 H, return", "f_p2_deg", deg(f_p2), "");
    row("ff_rab = π + β", "ff_rab_deg", deg(ff_rab), "");
    let phi_y_calc = f_p2.abs() + 0.5 * f_p1 - rad(10.0);
    let phi_s_calc = 0.5 * ff_rab + 0.5 * f_p1 - rad(15.0);
    row(
        "φ_y = |f_p2| + f_p1/2 − 10°",
        "phi_y_calc_deg",
        deg(phi_y_calc),
        "the course project then sets φ_y = 28°",
    );
    row(
        "φ_s = ff_rab/2 + f_p1/2 − 15°",
        "phi_s_calc_deg",
        deg(phi_s_calc),
        "the course project then sets φ_s = φ_y",
    );
    let (phi_y, phi_ds) = (rad(28.0), rad(15.0));
    let phi_s = phi_y;
    row(
        "φ_r = φ_y + φ_ds + φ_s",
        "phi_r_deg",
        deg(phi_y + phi_ds + phi_s),
        "",
    );

    // 2. The program: rise, far dwell, return, with the course project's law.
    let (h, arm, k) = (0.045, 0.15, 1.0);
    let law = Law::ConstantAcceleration { k };
    let program = Program::new(
        h,
        vec![
            Segment::Rise { angle: phi_y, law },
            Segment::Dwell { angle: phi_ds },
            Segment::Return { angle: phi_s, law },
        ],
    )?;
    heading(
        "2. The law: piecewise-constant acceleration, k = 1 (the course project's text says 2, its code 1)",
    );
    row(
        "a_q1 = 2(k+1)h/φ_y² [m/rad²]",
        "a_q1",
        program.at(0.5 * phi_y / (k + 1.0))?.0[2],
        "",
    );
    row(
        "a_q4 [m/rad²]",
        "a_q4",
        program.at(phi_y + phi_ds + phi_s - 1e-9)?.0[2],
        "",
    );
    row(
        "v_q max on the rise [m/rad]",
        "v_q_max_rise",
        program.at(phi_y / (k + 1.0))?.0[1],
        "",
    );
    row(
        "v_q min on the return [m/rad]",
        "v_q_max_return",
        program.at(phi_y + phi_ds + phi_s * k / (k + 1.0))?.0[1],
        "",
    );
    row("ψ_max = h/l_BN [°]", "psi_max_deg", deg(h / arm), "");
    println!(
        "(the course project's S_B printed (a_q1/k)φ² for the first branch; (a_q1/2)φ² is what v_q = a_q1·φ integrates to)"
    );

    // 3. The course project's design, read off its drawing.
    let drawn_rocker = |initial_angle: f64| {
        Cam::new(
            program.clone(),
            Follower::Rocker {
                arm,
                centre_distance: 0.2973,
                initial_angle,
                pivot_angle: -FRAC_PI_2,
            },
            Rotation::CounterClockwise,
        )
    };
    let drawn_cam = drawn_rocker(rad(54.0))?;
    let ((at_max, theta_max), (at_min, theta_min)) = drawn_cam.pressure_extremes()?;
    heading("3. The course project's design: a_w = 0.2973 m, φ20 = 54°, l_BN = 0.15 m");
    row(
        "r0 = |OK0| [m]",
        "r0",
        drawn_cam.base_radius(),
        "the course project reads 0.2413 off its drawing",
    );
    let k0 = drawn_cam.pitch(0.0)?.k;
    row("K0.x [m]", "K0.x", k0.x, "");
    row("K0.y [m]", "K0.y", k0.y, "");
    // The φ20 that would give the graphical r0 with a_w = 0.2973.
    let implied = bisect(
        |psi0| drawn_rocker(psi0).map_or(f64::NAN, |cam| cam.base_radius() - 0.2413),
        rad(45.0),
        rad(60.0),
    );
    row(
        "φ20 that gives r0 = 0.2413 [°]",
        "phi20_implied_by_r0_deg",
        deg(implied),
        "",
    );
    row(
        "r at the far dwell [m]",
        "r_far_dwell",
        drawn_cam.pitch(phi_y + 0.5 * phi_ds)?.k.norm(),
        "",
    );
    row(
        "θ max on the rise [°]",
        "theta_max_rise_deg",
        deg(theta_max),
        "",
    );
    row("  at φ [°]", "theta_max_rise_at_deg", deg(at_max), "");
    row(
        "θ min on the return [°]",
        "theta_min_return_deg",
        deg(theta_min),
        "over the 35° limit",
    );
    row("  at φ [°]", "theta_min_return_at_deg", deg(at_min), "");
    row("r_R min = 0.25·r0 [m]", "r_R_min", 0.25 * 0.2413, "");
    row("r_R max = 0.4·r0 [m]", "r_R_max", 0.4 * 0.2413, "");

    // 4. The smallest cam within the limit.
    let limit = rad(35.0);
    let best = smallest_rocker(&program, arm, -FRAC_PI_2, Rotation::CounterClockwise, limit)?;
    let Follower::Rocker {
        centre_distance,
        initial_angle,
        ..
    } = *best.follower()
    else {
        unreachable!("a rocker was asked for")
    };
    let ((best_at_max, best_max), (best_at_min, best_min)) = best.pressure_extremes()?;
    heading("4. The smallest cam with |θ| ≤ 35° on both strokes (solved, not drawn)");
    row("r0 [m]", "opt.r0_min", best.base_radius(), "");
    row("a_w [m]", "opt.a_w", centre_distance, "");
    row("φ20 [°]", "opt.phi20_deg", deg(initial_angle), "");
    println!(
        "θ max {:.9}° at φ = {:.3}°, θ min {:.9}° at φ = {:.3}°",
        deg(best_max),
        deg(best_at_max),
        deg(best_min),
        deg(best_at_min)
    );

    let (at_sharpest, largest) = best.largest_roller()?;
    println!(
        "the course project allows rollers of 0.25…0.4·r0 = {:.1}…{:.1} mm, but this cam's pitch curve bends with a radius of only {:.1} mm\n\
         at φ = {:.2}°: a roller above that undercuts (the profile would loop)",
        250.0 * best.base_radius(),
        400.0 * best.base_radius(),
        1000.0 * largest,
        deg(at_sharpest)
    );

    // 5. The profile for a roller of 0.25·r0.
    let roller = 0.25 * best.base_radius();
    let profile = best.profile(roller, 720)?;
    let convex = 1.0
        / profile
            .iter()
            .map(|p| p.curvature)
            .fold(f64::NEG_INFINITY, f64::max);
    println!(
        "\n5. The profile for a roller of r_R = {:.1} mm: no undercut; its smallest convex radius of curvature is {:.1} mm",
        roller * 1000.0,
        convex * 1000.0
    );
    let folder = output::folder("cam")?;
    let mut csv = String::from(
        "# The cam of the shaping machine, the smallest within |θ| ≤ 35°, roller r_R = 0.25·r0, 720 points over a turn;\n\
         # written by `cargo run --release --example cam`. Coordinates in the cam's frame, mm.\n\
         phi_deg,profile_x_mm,profile_y_mm,pitch_x_mm,pitch_y_mm,radius_mm\n",
    );
    for p in &profile {
        let _ = writeln!(
            csv,
            "{:.3},{:.6},{:.6},{:.6},{:.6},{:.6}",
            deg(p.phi),
            1000.0 * p.profile.x,
            1000.0 * p.profile.y,
            1000.0 * p.pitch.x,
            1000.0 * p.pitch.y,
            1000.0 / p.curvature
        );
    }
    let csv_path = folder.join("profile.csv");
    std::fs::write(&csv_path, csv)?;
    let drawing = folder.join("cam.svg");
    std::fs::write(
        &drawing,
        best.drawing(
            roller,
            best_at_min,
            &format!(
                "The smallest cam within ±35°, at φ = {:.0}° (its worst pressure angle)",
                deg(best_at_min)
            ),
            640.0,
        )?,
    )?;
    // The active part of the turn (the rest is the dwell at the base circle).
    let phis: Vec<f64> = (0..=500).map(|i| i as f64 * rad(100.0) / 500.0).collect();
    let curve = |f: &dyn Fn(f64) -> Result<f64, CamError>| -> Result<Vec<(f64, f64)>, CamError> {
        phis.iter().map(|&p| Ok((deg(p), f(p)?))).collect()
    };
    let motion = Chart::new(
        "The follower's program over φ = 0…100° (the rest of the turn a dwell)",
        "φ [°]",
    )
    .size(900, 230)
    .panel(Panel::new("S_B [mm]").line("S_B", curve(&|p| Ok(1000.0 * program.at(p)?.0[0]))?))
    .panel(Panel::new("v_q [mm/rad]").line("v_q", curve(&|p| Ok(1000.0 * program.at(p)?.0[1]))?))
    .panel(Panel::new("a_q [mm/rad²]").line("a_q", curve(&|p| Ok(1000.0 * program.at(p)?.0[2]))?));
    let motion_path = folder.join("motion.svg");
    std::fs::write(&motion_path, motion.render()?)?;
    let pressure = Chart::new("Pressure angle: the course project's design and the smallest cam within ±35° (φ = 0…100°, then a dwell)", "φ [°]")
        .size(900, 320)
        .panel(
            Panel::new("θ [°]")
                .line("the course project's (a_w = 0.2973 m, φ_20 = 54°)", curve(&|p| Ok(deg(drawn_cam.pressure_angle(p)?)))?)
                .line("the smallest within the limit", curve(&|p| Ok(deg(best.pressure_angle(p)?)))?)
                .levels("the limit, ±35°", &[35.0, -35.0]),
        );
    let pressure_path = folder.join("pressure.svg");
    std::fs::write(&pressure_path, pressure.render()?)?;
    for path in [drawing, motion_path, pressure_path, csv_path] {
        println!("wrote {}", path.display());
    }
    Ok(())
}
