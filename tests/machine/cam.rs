//! The cam of the course project against the 50-digit
//! reference, the motion laws at their joints, profiles against their
//! pitch curves, the sizing against its limit, and undercut.

use crate::machine;

use linkage::cam::{
    Cam, CamError, Follower, Law, Program, Rotation, Segment, smallest_rocker, smallest_translating,
};
use std::collections::HashMap;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

fn reference() -> HashMap<String, (f64, Option<String>)> {
    include_str!("../data/shaper_cam_reference.csv")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("key,"))
        .map(|l| {
            let cols: Vec<&str> = l.split(',').collect();
            let printed = (!cols[2].is_empty()).then(|| cols[2].to_string());
            (
                cols[0].to_string(),
                (cols[1].parse().unwrap_or(f64::NAN), printed),
            )
        })
        .collect()
}

const H: f64 = 0.045;
const ARM: f64 = 0.15;

fn course_program() -> Program {
    let law = Law::ConstantAcceleration { k: 1.0 };
    Program::new(
        H,
        vec![
            Segment::Rise {
                angle: 28f64.to_radians(),
                law,
            },
            Segment::Dwell {
                angle: 15f64.to_radians(),
            },
            Segment::Return {
                angle: 28f64.to_radians(),
                law,
            },
        ],
    )
    .unwrap()
}

fn rocker(program: &Program, a_w: f64, phi20_deg: f64) -> Cam {
    Cam::new(
        program.clone(),
        Follower::Rocker {
            arm: ARM,
            centre_distance: a_w,
            initial_angle: phi20_deg.to_radians(),
            pivot_angle: -FRAC_PI_2,
        },
        Rotation::CounterClockwise,
    )
    .unwrap()
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

fn ours() -> HashMap<&'static str, f64> {
    let mut out = HashMap::new();
    let data = machine::COURSE_PROJECT;
    let shaper = machine::synthesize(&data).unwrap();
    let m = machine::machine(&shaper, &data).unwrap();
    let x0 = m.analysis(0.0).unwrap().u[2];
    let travel = |phi: f64| m.analysis(phi).unwrap().u[2] - x0 - 0.05 * data.stroke;
    let (f_p1, f_p2) = (bisect(travel, 0.1, 1.0), bisect(travel, -1.0, -0.1));
    let ff_rab = PI + shaper.beta();
    out.insert("cam.f_p1_deg", f_p1.to_degrees());
    out.insert("cam.f_p2_deg", f_p2.to_degrees());
    out.insert("cam.ff_rab_deg", ff_rab.to_degrees());
    out.insert(
        "cam.phi_y_calc_deg",
        (f_p2.abs() + 0.5 * f_p1).to_degrees() - 10.0,
    );
    out.insert(
        "cam.phi_s_calc_deg",
        (0.5 * ff_rab + 0.5 * f_p1).to_degrees() - 15.0,
    );
    out.insert("cam.phi_r_deg", 28.0 + 15.0 + 28.0);
    out.insert("cam.k_used", 1.0);
    let program = course_program();
    let phi_y = 28f64.to_radians();
    out.insert("cam.a_q1", program.at(0.25 * phi_y).unwrap().0[2]);
    out.insert(
        "cam.a_q4",
        program.at(71f64.to_radians() - 1e-9).unwrap().0[2],
    );
    out.insert("cam.v_q_max_rise", program.at(0.5 * phi_y).unwrap().0[1]);
    out.insert(
        "cam.v_q_max_return",
        program.at((43.0f64 + 14.0).to_radians()).unwrap().0[1],
    );
    out.insert(
        "cam.psi_max_rad",
        program.at(35f64.to_radians()).unwrap().0[0] / ARM,
    );
    out.insert(
        "cam.psi_max_deg",
        (program.at(35f64.to_radians()).unwrap().0[0] / ARM).to_degrees(),
    );
    out.insert(
        "cam.check.SB_correct_at_phi_y_over_2",
        program.at(0.5 * phi_y).unwrap().0[0],
    );
    let drawn = rocker(&program, 0.2973, 54.0);
    let ((at_max, max), (at_min, min)) = drawn.pressure_extremes().unwrap();
    out.insert("cam.theta_max_rise_deg", max.to_degrees());
    out.insert("cam.theta_max_rise_at_deg", at_max.to_degrees());
    out.insert("cam.theta_min_return_deg", min.to_degrees());
    out.insert("cam.theta_min_return_at_deg", at_min.to_degrees());
    out.insert("cam.r0", drawn.base_radius());
    let k0 = drawn.pitch(0.0).unwrap().k;
    out.insert("cam.K0.x", k0.x);
    out.insert("cam.K0.y", k0.y);
    out.insert(
        "cam.phi20_implied_by_r0_deg",
        bisect(
            |d| rocker(&program, 0.2973, d).base_radius() - 0.2413,
            45.0,
            60.0,
        ),
    );
    out.insert("cam.r_R_min", 0.25 * 0.2413);
    out.insert("cam.r_R_max", 0.4 * 0.2413);
    out.insert(
        "cam.r_far_dwell",
        drawn.pitch(35f64.to_radians()).unwrap().k.norm(),
    );
    let best = smallest_rocker(
        &program,
        ARM,
        -FRAC_PI_2,
        Rotation::CounterClockwise,
        35f64.to_radians(),
    )
    .unwrap();
    let Follower::Rocker {
        centre_distance,
        initial_angle,
        ..
    } = *best.follower()
    else {
        panic!("a rocker")
    };
    out.insert("cam.opt.r0_min", best.base_radius());
    out.insert("cam.opt.a_w", centre_distance);
    out.insert("cam.opt.phi20_deg", initial_angle.to_degrees());
    out
}

#[test]
fn the_course_projects_cam_matches_the_50_digit_reference() {
    let reference = reference();
    let ours = ours();
    assert!(ours.len() >= 28, "{}", ours.len());
    for (key, value) in &ours {
        let (exact, printed) = reference.get(*key).unwrap_or_else(|| panic!("{key}"));
        // The optimum is found to the bisection's 1e-13 in r0; the angle and
        // centre distance that go with it are flat there.
        let tolerance = if key.starts_with("cam.opt.") {
            1e-8
        } else {
            1e-9
        };
        let error = (value - exact).abs() / exact.abs();
        assert!(
            error <= tolerance,
            "{key}: ours {value}, exact {exact}, {error:e}"
        );
        if let Some(text) = printed {
            let p: f64 = text.parse().unwrap();
            let decimals = text.split_once('.').map_or(0, |(_, d)| d.len()) as i32;
            let half = 0.5 * 10f64.powi(-decimals);
            if *key == "cam.r0" {
                // The course project's graphical reading: 0.2 % low.
                assert!((value - p) / p > 1e-3 && (value - p) / p < 3e-3);
            } else {
                assert!(
                    (value - p).abs() <= half,
                    "{key}: ours {value}, printed {text}"
                );
            }
        }
    }
}

/// The course project's pressure-angle formula for its rocker,
/// tan θ = (v_q + a_w cos(φ20 + ψ) − l)/(a_w sin(φ20 + ψ)), is what the
/// geometric definition (the common normal against the roller centre's
/// motion) gives.
#[test]
fn the_pressure_angle_is_the_course_projects_formula() {
    let program = course_program();
    let cam = rocker(&program, 0.2973, 54.0);
    for i in 0..720 {
        let phi = TAU * i as f64 / 720.0;
        let (s, _) = program.at(phi).unwrap();
        let psi = s[0] / ARM;
        let angle = 54f64.to_radians() + psi;
        let formula = ((s[1] + 0.2973 * angle.cos() - ARM) / (0.2973 * angle.sin())).atan();
        assert!(
            (cam.pressure_angle(phi).unwrap() - formula).abs() < 1e-13,
            "φ = {phi}"
        );
    }
}

#[test]
fn laws_join_at_the_segment_ends() {
    for law in [
        Law::ConstantAcceleration { k: 1.0 },
        Law::ConstantAcceleration { k: 2.5 },
        Law::Harmonic,
        Law::Cycloidal,
        Law::Polynomial345,
        Law::ModifiedTrapezoid,
    ] {
        let (rise, dwell, ret) = (0.9, 0.4, 1.3);
        let program = Program::new(
            0.02,
            vec![
                Segment::Rise { angle: rise, law },
                Segment::Dwell { angle: dwell },
                Segment::Return { angle: ret, law },
            ],
        )
        .unwrap();
        for (phi, s) in [
            (0.0, 0.0),
            (rise, 0.02),
            (rise + dwell, 0.02),
            (rise + dwell + ret, 0.0),
            (5.0, 0.0),
        ] {
            for side in [-1e-12, 1e-12] {
                let (d, _) = program.at(phi + side).unwrap();
                assert!((d[0] - s).abs() < 1e-12, "{law:?} at {phi}: s = {}", d[0]);
                assert!(d[1].abs() < 1e-9, "{law:?} at {phi}: s′ = {}", d[1]);
            }
        }
        // The laws smooth at their ends start and end at rest in
        // acceleration too.
        if matches!(
            law,
            Law::Cycloidal | Law::Polynomial345 | Law::ModifiedTrapezoid
        ) {
            for phi in [0.0, rise, rise + dwell, rise + dwell + ret] {
                for side in [-1e-12, 1e-12] {
                    assert!(
                        program.at(phi + side).unwrap().0[2].abs() < 1e-8,
                        "{law:?} at {phi}"
                    );
                }
            }
        }
        // The return is the rise run backwards.
        for i in 1..10 {
            let x = i as f64 / 10.0;
            let up = program.at(x * rise).unwrap().0;
            let down = program.at(rise + dwell + (1.0 - x) * ret).unwrap().0;
            assert!((up[0] - down[0]).abs() < 1e-12);
        }
    }
}

/// The distance from a point to the pitch curve: coarse over the turn,
/// then refined near the closest sample.
fn distance_to_pitch(cam: &Cam, p: nalgebra::Vector2<f64>) -> f64 {
    let n = 2880;
    let d = |phi: f64| (cam.pitch(phi).unwrap().k - p).norm();
    let k = (0..n)
        .min_by(|&a, &b| d(TAU * a as f64 / n as f64).total_cmp(&d(TAU * b as f64 / n as f64)))
        .unwrap();
    let (mut lo, mut hi) = (
        TAU * (k as f64 - 1.0) / n as f64,
        TAU * (k as f64 + 1.0) / n as f64,
    );
    // Golden section.
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..200 {
        let (a, b) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if d(a) < d(b) {
            hi = b;
        } else {
            lo = a;
        }
    }
    d(0.5 * (lo + hi))
}

#[test]
fn the_profile_keeps_the_roller_radius_from_the_pitch_curve() {
    let program = course_program();
    let best = smallest_rocker(
        &program,
        ARM,
        -FRAC_PI_2,
        Rotation::CounterClockwise,
        35f64.to_radians(),
    )
    .unwrap();
    // The course project allows rollers up to 0.4·r0, but this cam's pitch curve has
    // a convex radius of only 76.6 mm on its flanks: a roller that large
    // undercuts.
    let (at, largest) = best.largest_roller().unwrap();
    assert!(
        (largest - 0.0766).abs() < 5e-4,
        "{largest} at {}",
        at.to_degrees()
    );
    assert!(matches!(
        best.profile(0.4 * best.base_radius(), 720),
        Err(CamError::Undercut { .. })
    ));
    for roller in [0.25 * best.base_radius(), 0.99 * largest] {
        let profile = best.profile(roller, 360).unwrap();
        let mut worst: f64 = 0.0;
        for p in profile.iter().step_by(3) {
            worst = worst.max((distance_to_pitch(&best, p.profile) - roller).abs());
        }
        assert!(worst <= 1e-9, "roller {roller}: {worst:e}");
    }
}

#[test]
fn the_smallest_cams_reach_the_limit_exactly() {
    let program = course_program();
    let limit = 35f64.to_radians();
    let best =
        smallest_rocker(&program, ARM, -FRAC_PI_2, Rotation::CounterClockwise, limit).unwrap();
    let ((_, max), (_, min)) = best.pressure_extremes().unwrap();
    assert!(
        (max.max(-min) - limit).abs() < 1e-6 * limit,
        "{} {}",
        max,
        min
    );
    // A smaller one would exceed it, whatever its arm angle.
    // A translating follower with a cycloidal rise, both senses.
    let cycloidal = Program::new(
        0.03,
        vec![
            Segment::Rise {
                angle: 1.2,
                law: Law::Cycloidal,
            },
            Segment::Dwell { angle: 0.5 },
            Segment::Return {
                angle: 1.6,
                law: Law::Polynomial345,
            },
        ],
    )
    .unwrap();
    for rotation in [Rotation::CounterClockwise, Rotation::Clockwise] {
        let best =
            smallest_translating(&cycloidal, FRAC_PI_2, rotation, 30f64.to_radians()).unwrap();
        let ((_, max), (_, min)) = best.pressure_extremes().unwrap();
        assert!(
            (max.max(-min) - 30f64.to_radians()).abs() < 1e-6,
            "{rotation:?}: {} {}",
            max.to_degrees(),
            min.to_degrees()
        );
        // Without offset, tan θ = s′/(r0 + s) (the textbook's formula).
        let Follower::Translating { base, .. } = *best.follower() else {
            panic!()
        };
        let centred = Cam::new(
            best.program().clone(),
            Follower::Translating {
                offset: 0.0,
                base,
                axis_angle: FRAC_PI_2,
            },
            best.rotation(),
        )
        .unwrap();
        for i in 0..100 {
            let phi = 3.3 * i as f64 / 100.0;
            let (s, _) = cycloidal.at(phi).unwrap();
            let textbook = (s[1] / (base + s[0])).atan();
            assert!(
                (centred.pressure_angle(phi).unwrap().abs() - textbook.abs()).abs() < 1e-12,
                "φ = {phi}: {} vs {textbook}",
                centred.pressure_angle(phi).unwrap()
            );
        }
    }
}

/// The four cams of `tests/data/cam_pressure_extremes.csv`, by name: a
/// rocker and a translating follower with an offset, each turning either
/// way, their laws smooth inside the segments (the extremes fall inside
/// them, where dθ/dφ = 0).
fn smooth_cam(name: &str) -> Cam {
    let rocker_program = Program::new(
        0.045,
        vec![
            Segment::Rise {
                angle: 1.2,
                law: Law::Cycloidal,
            },
            Segment::Dwell { angle: 0.5 },
            Segment::Return {
                angle: 1.6,
                law: Law::Polynomial345,
            },
        ],
    )
    .unwrap();
    let translating_program = Program::new(
        0.03,
        vec![
            Segment::Rise {
                angle: 1.5,
                law: Law::Harmonic,
            },
            Segment::Dwell { angle: 0.3 },
            Segment::Return {
                angle: 1.4,
                law: Law::Cycloidal,
            },
        ],
    )
    .unwrap();
    let (kind, sense) = name.rsplit_once('_').unwrap();
    let rotation = match sense {
        "ccw" => Rotation::CounterClockwise,
        "cw" => Rotation::Clockwise,
        _ => panic!("{name}"),
    };
    let (program, follower) = match kind {
        "rocker" => (
            rocker_program,
            Follower::Rocker {
                arm: 0.15,
                centre_distance: 0.3,
                initial_angle: 0.9,
                pivot_angle: -FRAC_PI_2,
            },
        ),
        "translating" => (
            translating_program,
            Follower::Translating {
                offset: 0.01,
                base: 0.05,
                axis_angle: FRAC_PI_2,
            },
        ),
        _ => panic!("{name}"),
    };
    Cam::new(program, follower, rotation).unwrap()
}

/// Where the pressure angle is largest and smallest, against the 50-digit
/// reference (roots of dθ/dφ found by mpmath from the geometric definition,
/// `benches/reference/cam_pressure_extremes.py`): the cam angle to what
/// [`Cam::pressure_extremes`] states, the values to rounding.
#[test]
fn the_pressure_extremes_sit_where_the_reference_puts_them() {
    let rows: Vec<Vec<&str>> = include_str!("../data/cam_pressure_extremes.csv")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("cam,"))
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(rows.len(), 8);
    let (mut worst_at, mut worst_value): (f64, f64) = (0.0, 0.0);
    for row in &rows {
        let (phi, theta): (f64, f64) = (row[2].parse().unwrap(), row[3].parse().unwrap());
        let (max, min) = smooth_cam(row[0]).pressure_extremes().unwrap();
        let (at, value) = match row[1] {
            "max" => max,
            "min" => min,
            _ => panic!("{row:?}"),
        };
        let (error_at, error_value) = ((at - phi).abs(), (value - theta).abs());
        println!(
            "{} {}: φ off by {error_at:.1e} rad, θ by {error_value:.1e}",
            row[0], row[1]
        );
        worst_at = worst_at.max(error_at);
        worst_value = worst_value.max(error_value);
    }
    println!("worst: φ {worst_at:.1e} rad, θ {worst_value:.1e} rad");
    // θ of 0.2 to 0.7 rad: to rounding (a few units in the last place).
    assert!(worst_value <= 1e-15, "θ off by {worst_value:e}");
    // What the documentation states (measured: 1.3e-15 rad; Brent's search
    // on the value alone placed them only to 4.8e-9 rad).
    assert!(worst_at <= 1e-14, "φ off by {worst_at:e} rad");
}

#[test]
fn an_undercut_is_an_error_naming_the_angles() {
    let program = course_program();
    let cam = rocker(&program, 0.2973, 54.0);
    // A roller larger than the pitch curve's sharpest convex radius.
    let err = cam.profile(0.2, 720).unwrap_err();
    match err {
        CamError::Undercut { roller, ranges } => {
            assert_eq!(roller, 0.2);
            assert!(!ranges.is_empty());
            for (from, to) in ranges {
                assert!(from <= to && (0.0..=72.0).contains(&from), "{from}..{to}");
            }
        }
        other => panic!("{other}"),
    }
    assert!(cam.profile(0.06, 720).is_ok());
    assert!(matches!(
        Program::new(0.01, vec![Segment::Dwell { angle: 7.0 }]),
        Err(CamError::TooLong { .. })
    ));
}

/// Settings out of their range are typed errors, never a hang or a
/// meaningless cam: a rocker arm of 0 once widened its bracket from 0 to 0
/// forever, a negative one gave a base radius of −11, a NaN limit or one of
/// 90° or more returned a cam of 0.055 m or 1.4e-6 m.
#[test]
fn bad_settings_are_typed_errors() {
    let program = course_program();
    let limit = 35f64.to_radians();
    let bad = |result: Result<Cam, CamError>, what: &str| {
        assert!(
            matches!(result, Err(CamError::BadSetting { .. })),
            "{what}: {result:?}"
        );
    };
    for arm in [0.0, -0.15, f64::NAN, f64::INFINITY, -0.0] {
        bad(
            smallest_rocker(&program, arm, -FRAC_PI_2, Rotation::CounterClockwise, limit),
            &format!("arm {arm}"),
        );
    }
    for limit in [
        f64::NAN,
        0.0,
        -0.1,
        FRAC_PI_2,
        100f64.to_radians(),
        f64::INFINITY,
    ] {
        bad(
            smallest_rocker(&program, ARM, -FRAC_PI_2, Rotation::CounterClockwise, limit),
            &format!("rocker, limit {limit}"),
        );
        bad(
            smallest_translating(&program, FRAC_PI_2, Rotation::CounterClockwise, limit),
            &format!("translating, limit {limit}"),
        );
    }
    bad(
        smallest_rocker(&program, ARM, f64::NAN, Rotation::CounterClockwise, limit),
        "pivot angle NaN",
    );
    let rocker = |arm, centre_distance, initial_angle, pivot_angle| Follower::Rocker {
        arm,
        centre_distance,
        initial_angle,
        pivot_angle,
    };
    for follower in [
        rocker(0.0, 0.3, 1.0, 0.0),
        rocker(0.15, -0.3, 1.0, 0.0),
        rocker(0.15, 0.3, f64::NAN, 0.0),
        rocker(0.15, 0.3, 1.0, f64::INFINITY),
        Follower::Translating {
            offset: 0.2,
            base: 0.1,
            axis_angle: 0.0,
        },
        Follower::Translating {
            offset: 0.0,
            base: 0.0,
            axis_angle: 0.0,
        },
    ] {
        bad(
            Cam::new(program.clone(), follower, Rotation::Clockwise),
            &format!("{follower:?}"),
        );
    }
    let cam = rocker_cam(&program);
    assert!(matches!(
        cam.pitch(f64::NAN),
        Err(CamError::BadSetting { .. })
    ));
    assert!(matches!(
        program.at(f64::INFINITY),
        Err(CamError::BadSetting { .. })
    ));
    assert!(matches!(
        cam.profile(0.01, 0),
        Err(CamError::BadSetting { .. })
    ));
    assert!(matches!(
        cam.profile(0.01, usize::MAX),
        Err(CamError::BadSetting { .. })
    ));
    #[cfg(feature = "draw")]
    assert!(matches!(
        cam.drawing(0.01, 0.0, "", f64::NAN),
        Err(CamError::BadSetting { .. })
    ));
    assert!(matches!(
        cam.pressure_excess(f64::NAN),
        Err(CamError::BadSetting { .. })
    ));
    assert!(matches!(
        Program::new(
            0.04,
            vec![Segment::Rise {
                angle: 1.0,
                law: Law::ConstantAcceleration { k: -1.0 }
            }]
        ),
        Err(CamError::BadSetting { .. })
    ));
}

fn rocker_cam(program: &Program) -> Cam {
    rocker(program, 0.2973, 54.0)
}

/// The drawing names everything it draws. Each legend swatch is drawn with
/// the stroke, dash and width of exactly one element of the picture (a
/// solid swatch for dashed curves, or one swatch for two curves, fails);
/// every other stroked element has a label `label-{id}` inside the picture;
/// and the scale bar is a round number of mm whose length in pixels agrees
/// with the picture's scale, read off the base circle's radius.
#[cfg(feature = "draw")]
#[test]
fn the_drawing_names_what_it_draws_and_has_a_true_scale_bar() {
    let program = course_program();
    let limit = 35f64.to_radians();
    let cams = [
        smallest_rocker(&program, ARM, -FRAC_PI_2, Rotation::CounterClockwise, limit).unwrap(),
        smallest_translating(&program, FRAC_PI_2, Rotation::Clockwise, limit).unwrap(),
    ];
    for (cam, phi, width) in [(&cams[0], 1.0, 640.0), (&cams[1], 0.7, 420.0)] {
        let roller = 0.25 * cam.base_radius();
        let svg = cam.drawing(roller, phi, "a cam", width).unwrap();
        check_drawing(&svg, 1000.0 * (cam.base_radius() - roller));
    }
}

/// The checks of the test above on one drawing, whose base circle has the
/// radius `base_circle_mm`.
#[cfg(feature = "draw")]
fn check_drawing(svg: &str, base_circle_mm: f64) {
    use roxmltree::{Document, Node};
    let doc = Document::parse(svg).unwrap();
    let by_id = |id: &str| {
        doc.descendants()
            .find(|n| n.attribute("id") == Some(id))
            .unwrap_or_else(|| panic!("no element {id:?} in\n{svg}"))
    };
    let number = |n: Node, name: &str| -> f64 {
        n.attribute(name)
            .and_then(|v| v.parse().ok())
            .unwrap_or_else(|| panic!("{name} of {n:?}"))
    };
    /// How an element is stroked: colour, dash pattern, width.
    fn style<'a>(n: Node<'a, '_>) -> [Option<&'a str>; 3] {
        [
            n.attribute("stroke"),
            n.attribute("stroke-dasharray"),
            n.attribute("stroke-width"),
        ]
    }
    let legend = by_id("legend");
    let drawn: Vec<Node> = doc
        .descendants()
        .filter(|n| n.has_attribute("stroke") && !n.ancestors().any(|a| a == legend))
        .collect();
    let swatches: Vec<Node> = legend
        .descendants()
        .filter(|n| n.attribute("class") == Some("swatch"))
        .collect();
    assert!(swatches.len() >= 5, "{} swatches", swatches.len());
    for swatch in &swatches {
        let matching: Vec<_> = drawn
            .iter()
            .filter(|d| style(**d) == style(*swatch))
            .map(|d| d.attribute("id"))
            .collect();
        assert_eq!(
            matching.len(),
            1,
            "the swatch drawn as {:?} matches {matching:?}",
            style(*swatch)
        );
    }
    let (width, height) = (
        number(doc.root_element(), "width"),
        number(doc.root_element(), "height"),
    );
    for element in &drawn {
        if swatches.iter().any(|s| style(*s) == style(*element)) {
            continue;
        }
        let id = element
            .attribute("id")
            .unwrap_or_else(|| panic!("an unnamed element {element:?}"));
        let label = by_id(&format!("label-{id}"));
        assert!(
            label.text().is_some_and(|t| !t.trim().is_empty()),
            "{id}'s label is empty"
        );
        let (x, y) = (number(label, "x"), number(label, "y"));
        assert!(
            (0.0..width).contains(&x) && (0.0..height).contains(&y),
            "{id}'s label at ({x}, {y}) is off the picture"
        );
    }
    // The scale bar: "M x y v-4 v8 v-4 h<length> v-4 v8" and "<n> mm".
    let bar = by_id("scale-bar").attribute("d").unwrap();
    let pixels: f64 = bar
        .split_whitespace()
        .find_map(|step| step.strip_prefix('h'))
        .and_then(|h| h.parse().ok())
        .unwrap_or_else(|| panic!("no horizontal stroke in the scale bar {bar:?}"));
    let text = by_id("scale-label").text().unwrap().trim().to_string();
    let mm: f64 = text
        .strip_suffix(" mm")
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("the scale bar reads {text:?}"));
    let decade = 10f64.powf(mm.log10().floor());
    assert!(
        [1.0, 2.0, 5.0]
            .iter()
            .any(|m| (mm / decade - m).abs() < 1e-9),
        "{mm} mm is not a round length"
    );
    let px_per_mm = number(by_id("base-circle"), "r") / base_circle_mm;
    assert!(
        (pixels / px_per_mm - mm).abs() < 1e-3 * mm,
        "the bar of {pixels} px stands for {} mm, not {mm} mm",
        pixels / px_per_mm
    );
    assert!((20.0..=150.0).contains(&pixels), "a bar of {pixels} px");
}
