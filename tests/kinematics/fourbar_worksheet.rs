//! The Maple worksheet's four-bar, number by number, against the reference
//! recomputed at 50 digits (`tests/data/fourbar_worksheet.csv`), and the 360-pose
//! sweep (`tests/data/fourbar_sweep.csv`).

use crate::common::{FourBar, OMEGA2, rel};
use linkage::prelude::*;
use std::collections::HashMap;

/// key → value, from the reference CSV.
fn reference() -> HashMap<String, f64> {
    let text = include_str!("../data/fourbar_worksheet.csv");
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("key,"))
        .filter_map(|l| {
            let mut parts = l.split(',');
            let key = parts.next()?;
            let value = parts.next()?.parse::<f64>().ok()?;
            Some((key.to_owned(), value))
        })
        .collect()
}

/// Keys of the reference that are not quantities of this analysis, with the
/// reason.
const NOT_KINEMATICS: [(&str, &str); 13] = [
    (
        "residual_",
        "Maple's Digits=10 round-off residual; ours is checked to be ~0 instead",
    ),
    (
        "check.printed_u2pu_formula_absdiff",
        "a check of the worksheet's printed formula",
    ),
    (
        "check.velocity_residual_norm",
        "checked directly (Ψ_u u̇ + Ψ_v v̇)",
    ),
    (
        "check.acc_methods",
        "checked directly (method A − method B)",
    ),
    (
        "sweep.check.acc_methods_max_absdiff",
        "checked directly over the sweep",
    ),
    (
        "maple_coeff.",
        "coefficients of Maple's printed simplification",
    ),
    (
        "omega4_coeff_l2w2_over_l4",
        "a coefficient of Maple's printed formula",
    ),
    ("grashof.", "Grashof classes: the stability tests"),
    (
        "sweep_l2_40.",
        "the change-point four-bar: the stability tests",
    ),
    (
        "extra_nongrashof_l2_45.",
        "the non-Grashof four-bar: the stability tests",
    ),
    ("sweep.alpha3.cont_", "extrema of α need the jerk"),
    ("sweep.alpha4.cont_", "extrema of α need the jerk"),
    (
        "dist_",
        "distances between the worksheet's points (checked as link lengths below)",
    ),
];

struct Worksheet {
    values: HashMap<String, f64>,
}

impl Worksheet {
    /// Every quantity of the worksheet at θ2 = 20°, ω2 = 400 rpm, α2 = 0,
    /// computed through the public API.
    fn compute() -> Worksheet {
        let bar = FourBar::WORKSHEET;
        let theta2 = 20f64.to_radians();
        let v = vector![theta2];
        let guess = vector![70f64.to_radians(), -50f64.to_radians()];
        let mut iterates = Vec::new();
        let position = bar
            .solve_position_observed(&guess, &v, &Options::default(), |it| iterates.push(it.u))
            .unwrap();
        let a = bar
            .analyze(
                &guess,
                &v,
                &vector![OMEGA2],
                &vector![0.0],
                &Options::default(),
            )
            .unwrap();
        assert_eq!(a.u, position.u);
        let mut values = HashMap::new();
        let mut put = |k: &str, x: f64| {
            values.insert(k.to_owned(), x);
        };
        put("l1", bar.l1);
        put("l2", bar.l2);
        put("l3", bar.l3);
        put("l4", bar.l4);
        put("theta2", theta2);
        put("omega2", OMEGA2);
        put("alpha2", 0.0);
        put("theta3_0", guess[0]);
        put("theta4_0", guess[1]);
        for (k, u) in iterates.iter().enumerate().skip(1).take(4) {
            put(&format!("nr.u{k}.theta3"), u[0]);
            put(&format!("nr.u{k}.theta4"), u[1]);
        }
        put("theta3", a.u[0]);
        put("theta4", a.u[1]);
        put("theta3_deg", a.u[0].to_degrees());
        put("theta4_deg", a.u[1].to_degrees());
        put("four_bar_note.phi3_deg", a.u[0].to_degrees());
        put("four_bar_note.phi4_deg", a.u[1].to_degrees() + 180.0);
        put("omega3", a.udot[0]);
        put("omega4", a.udot[1]);
        put("alpha3", a.uddot[0]);
        put("alpha4", a.uddot[1]);
        let b = bar
            .acceleration(
                &a.u,
                &v,
                &a.udot,
                &vector![OMEGA2],
                &vector![0.0],
                &Options {
                    method: AccelerationMethod::B,
                    ..Options::default()
                },
            )
            .unwrap();
        put("alpha3_gamma_method", b[0]);
        put("alpha4_gamma_method", b[1]);
        put("det_psi_u", bar.psi_u(&a.u, &v).determinant());

        let index = |name| bar.point_index(name).unwrap();
        let [pb, pc, g2, g3, g4] = ["B", "C", "G2", "G3", "G4"].map(index);
        let p = |k: usize| a.points[k];
        let vel = |k: usize| a.point_velocities[k];
        let acc = |k: usize| a.point_accelerations[k];
        let d = vector![bar.l1, 0.0];
        let mut put2 = |k: &str, w: Vector2<f64>| {
            put(&format!("{k}.x"), w.x);
            put(&format!("{k}.y"), w.y);
        };
        put2("B", p(pb));
        put2("PB", p(pb));
        put2("C", p(pc));
        put2("PC", p(pc));
        put2("D", d);
        put2("G2", p(g2));
        put2("PG3", p(g3));
        put2("PG4", p(g4));
        put2("BG3", p(g3) - p(pb));
        put2("CG4", p(g4) - p(pc));
        put2("DG4", p(g4) - d);
        put2("VG2", vel(g2));
        put2("VB", vel(pb));
        put2("VG3", vel(g3));
        put2("VG3_B", vel(g3) - vel(pb));
        put2("VC", vel(pc));
        put2("VG4", vel(g4));
        put2("VG4_C", vel(g4) - vel(pc));
        // D through the chain B → C → D: its velocity and acceleration vanish.
        put2("VD", vel(g4) * 2.0 - vel(pc));
        put2("AcD", acc(g4) * 2.0 - acc(pc));
        put2("AG2", acc(g2));
        put2("AcB", acc(pb));
        put2("AG3", acc(g3));
        put2("AcC", acc(pc));
        put2("AG4", acc(g4));
        // The worksheet's velocity arrows: tips at PG + 0.02·VG.
        put2("ext_V2", p(g2) + vel(g2) * 0.02);
        put2("ext_V3", p(g3) + vel(g3) * 0.02);
        put2("ext_V4", p(g4) + vel(g4) * 0.02);
        Worksheet { values }
    }
}

#[test]
fn every_worksheet_number_to_1e_12() {
    let reference = reference();
    let ours = Worksheet::compute();
    let sweep = sweep_extrema();
    let mut checked = 0;
    let mut worst: f64 = 0.0;
    let mut unexplained = Vec::new();
    for (key, &expected) in &reference {
        let got = ours.values.get(key).or_else(|| sweep.get(key));
        match got {
            Some(&got) => {
                // Quantities that are exactly zero (the ground pivot's
                // velocity) are compared against the size of their peers.
                let floor = if expected.abs() < 1e-20 {
                    1e3
                } else {
                    f64::MIN_POSITIVE
                };
                let r = rel(got, expected, floor);
                worst = worst.max(r);
                assert!(
                    r <= 1e-12,
                    "{key}: ours {got:e}, reference {expected:e}, relative {r:.1e}"
                );
                checked += 1;
            }
            None => {
                if !NOT_KINEMATICS
                    .iter()
                    .any(|(prefix, _)| key.starts_with(prefix))
                {
                    unexplained.push(key.clone());
                }
            }
        }
    }
    assert!(
        unexplained.is_empty(),
        "reference keys neither checked nor explained: {unexplained:?}"
    );
    eprintln!("{checked} reference values checked, worst relative error {worst:.1e}");
    assert!(checked >= 130, "only {checked} reference values checked");
}

#[test]
fn link_lengths_and_residual() {
    let bar = FourBar::WORKSHEET;
    let v = vector![20f64.to_radians()];
    let a = bar
        .analyze(
            &vector![70f64.to_radians(), -50f64.to_radians()],
            &v,
            &vector![OMEGA2],
            &vector![0.0],
            &Options::default(),
        )
        .unwrap();
    let [pb, pc, _, _, g4] = a.points;
    let d = vector![80.0, 0.0];
    assert!(rel(pb.norm(), 20.0, 0.0) < 1e-15);
    assert!(rel((pc - pb).norm(), 50.0, 0.0) < 1e-15);
    assert!(rel((d - pc).norm(), 70.0, 0.0) < 1e-15);
    assert!(rel((g4 - pc).norm(), 35.0, 0.0) < 1e-15);
    // The worksheet's residual is ±1e-8 (Digits=10); ours is at rounding level.
    assert!(bar.psi(&a.u, &v).amax() < 1e-13);
}

/// Newton from (70°, −50°) converges quadratically: the worksheet's four
/// iterates, then machine precision.
#[test]
fn newton_iterates_converge_quadratically() {
    let mut residuals = Vec::new();
    FourBar::WORKSHEET
        .solve_position_observed(
            &vector![70f64.to_radians(), -50f64.to_radians()],
            &vector![20f64.to_radians()],
            &Options::default(),
            |it| residuals.push(it.residual),
        )
        .unwrap();
    assert!(residuals[0] > 0.5);
    assert!(residuals[1] < 1e-2 * residuals[0]);
    assert!(residuals[2] < 1e-4 * residuals[1].max(1e-12));
    assert!(*residuals.last().unwrap() < 1e-13);
    assert!(residuals.len() <= 6, "{residuals:?}");
}

/// One sweep row: θ2 (deg) and the six columns.
fn sweep_reference() -> Vec<[f64; 7]> {
    include_str!("../data/fourbar_sweep.csv")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("theta2"))
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3], v[4], v[5], v[6]]
        })
        .collect()
}

/// The analysis over the 1° grid by continuation.
fn sweep_ours() -> Vec<[f64; 7]> {
    let mut u = vector![78f64.to_radians(), -44f64.to_radians()];
    (0..360)
        .map(|deg| {
            let theta2 = f64::from(deg).to_radians();
            let a = FourBar::WORKSHEET
                .analyze(
                    &u,
                    &vector![theta2],
                    &vector![OMEGA2],
                    &vector![0.0],
                    &Options::default(),
                )
                .unwrap();
            u = a.u;
            [
                f64::from(deg),
                a.u[0].to_degrees(),
                a.u[1].to_degrees(),
                a.udot[0],
                a.udot[1],
                a.uddot[0],
                a.uddot[1],
            ]
        })
        .collect()
}

#[test]
fn sweep_of_360_poses_to_1e_11() {
    let reference = sweep_reference();
    let ours = sweep_ours();
    assert_eq!(reference.len(), 360);
    let names = ["θ3", "θ4", "ω3", "ω4", "α3", "α4"];
    let mut worst = [0.0_f64; 6];
    for c in 1..7 {
        // Near a zero crossing a relative error is meaningless: within a
        // thousandth of the column's largest value of zero, the error is
        // measured against that thousandth.
        let scale = reference.iter().map(|r| r[c].abs()).fold(0.0, f64::max);
        for (r, o) in reference.iter().zip(&ours) {
            let e = rel(o[c], r[c], 1e-3 * scale);
            assert!(
                e <= 1e-11,
                "{} at θ2 = {}°: ours {}, reference {}, relative {e:.1e}",
                names[c - 1],
                r[0],
                o[c],
                r[c]
            );
            worst[c - 1] = worst[c - 1].max(e);
        }
    }
    eprintln!(
        "worst relative error over the sweep: {:?}",
        names.iter().zip(worst).collect::<Vec<_>>()
    );
}

/// The sweep's extremes on the 1° grid, and the continuous extrema of θ and
/// ω: θ3 is extreme where ω3 = 0, ω3 where α3 = 0 (α2 = 0), found by the
/// secant method on our own analysis.
fn sweep_extrema() -> HashMap<String, f64> {
    let ours = sweep_ours();
    let mut out = HashMap::new();
    let names = [
        "theta3_deg",
        "theta4_deg",
        "omega3",
        "omega4",
        "alpha3",
        "alpha4",
    ];
    for (c, name) in names.iter().enumerate() {
        let col = |r: &[f64; 7]| r[c + 1];
        let min = ours
            .iter()
            .min_by(|a, b| col(a).total_cmp(&col(b)))
            .unwrap();
        let max = ours
            .iter()
            .max_by(|a, b| col(a).total_cmp(&col(b)))
            .unwrap();
        out.insert(format!("sweep.{name}.min"), col(min));
        out.insert(format!("sweep.{name}.min_at_theta2_deg"), min[0]);
        out.insert(format!("sweep.{name}.max"), col(max));
        out.insert(format!("sweep.{name}.max_at_theta2_deg"), max[0]);
    }
    let det = |deg: f64| {
        let u = pose_near(deg, &ours);
        FourBar::WORKSHEET
            .psi_u(&u, &vector![deg.to_radians()])
            .determinant()
    };
    let (at, min_det) = ours
        .iter()
        .map(|r| (r[0], det(r[0]).abs()))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap();
    out.insert("sweep.min_abs_det_psi_u".into(), min_det);
    out.insert("sweep.min_abs_det_psi_u_at_theta2_deg".into(), at);
    for deg in [0.0, 180.0] {
        let u = pose_near(deg, &ours);
        out.insert(
            format!("sweep.transmission_angle_deg_at_{deg}"),
            180.0 - (u[0] - u[1]).to_degrees(),
        );
    }
    // Continuous extrema: a derivative vanishes; bracket on the grid, then
    // the secant method.
    for (quantity, derivative, name) in [
        (0usize, 2usize, "theta3_deg"),
        (1, 3, "theta4_deg"),
        (2, 4, "omega3"),
        (3, 5, "omega4"),
    ] {
        let f = |deg: f64| analysis_at(deg, &ours)[derivative];
        let g = |deg: f64| analysis_at(deg, &ours)[quantity];
        let mut found: Vec<(f64, f64)> = Vec::new();
        for w in ours
            .windows(2)
            .chain(std::iter::once(&[ours[359], ours[0]][..]))
        {
            let (a, b) = (w[0][0], if w[1][0] == 0.0 { 360.0 } else { w[1][0] });
            let (fa, fb) = (w[0][derivative + 1], w[1][derivative + 1]);
            if fa == 0.0 || fa.signum() != fb.signum() {
                let root = secant(&f, a, b);
                found.push((root, g(root)));
            }
        }
        let to_out = |x: f64| {
            if name.ends_with("deg") {
                x.to_degrees()
            } else {
                x
            }
        };
        let min = found.iter().min_by(|a, b| a.1.total_cmp(&b.1)).unwrap();
        let max = found.iter().max_by(|a, b| a.1.total_cmp(&b.1)).unwrap();
        out.insert(format!("sweep.{name}.cont_min"), to_out(min.1));
        out.insert(format!("sweep.{name}.cont_min_at_theta2_deg"), min.0);
        out.insert(format!("sweep.{name}.cont_max"), to_out(max.1));
        out.insert(format!("sweep.{name}.cont_max_at_theta2_deg"), max.0);
    }
    out
}

/// The worksheet branch's pose at θ2 (degrees), by Newton from the nearest
/// grid pose of the sweep.
fn pose_near(deg: f64, sweep: &[[f64; 7]]) -> SVector<f64, 2> {
    let row = &sweep[(deg.rem_euclid(360.0).round() as usize) % 360];
    let guess = vector![row[1].to_radians(), row[2].to_radians()];
    FourBar::WORKSHEET
        .solve_position(&guess, &vector![deg.to_radians()], &Options::default())
        .unwrap()
        .u
}

/// [θ3, θ4, ω3, ω4, α3, α4] at θ2 in degrees (rad and rad/s units).
fn analysis_at(deg: f64, sweep: &[[f64; 7]]) -> [f64; 6] {
    let u = pose_near(deg, sweep);
    let a = FourBar::WORKSHEET
        .analyze(
            &u,
            &vector![deg.to_radians()],
            &vector![OMEGA2],
            &vector![0.0],
            &Options::default(),
        )
        .unwrap();
    [a.u[0], a.u[1], a.udot[0], a.udot[1], a.uddot[0], a.uddot[1]]
}

/// A root of f in [a, b] by regula falsi with the Illinois modification
/// (superlinear, and the bracket always shrinks).
fn secant(f: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let (mut fa, mut fb) = (f(a), f(b));
    let mut side = 0;
    for _ in 0..200 {
        let x = (a * fb - b * fa) / (fb - fa);
        let fx = f(x);
        if fx == 0.0 || (b - a).abs() < 1e-12 * b.abs().max(1.0) {
            return x;
        }
        if fx.signum() == fb.signum() {
            b = x;
            fb = fx;
            if side == -1 {
                fa *= 0.5;
            }
            side = -1;
        } else {
            a = x;
            fa = fx;
            if side == 1 {
                fb *= 0.5;
            }
            side = 1;
        }
    }
    0.5 * (a + b)
}
