//! Assembly without a guess (`linkage::assembly`): every mechanism of the
//! repository assembled in each of its modes, the counts and the
//! coordinates against an independent elimination, the dead centre apart,
//! the typed errors, and the picks.
//!
//! The reference numbers are benches/reference/assembly_modes.py's
//! (tests/data/assembly_modes.csv): each mechanism's equations reduced to
//! one polynomial in the tangent of a half angle (a resultant for the
//! Stephenson III six-bar, whose loops are coupled) and its real roots
//! counted and located with SymPy and mpmath at 50 digits, copied here to
//! 20 digits.
// The reference's digits as printed, beyond the 17 an f64 keeps.
#![allow(clippy::excessive_precision)]

use crate::models::{
    BOOM, Coupler, FIVE_BAR, SIX_BAR, SLIDER_CRANK, SLIDER_DRIVEN, STEPHENSON_THREE, WATT_SIX_BAR,
};
use linkage::assembly::{Assemble, AssemblyError, Lengths, Modes, Pick, Search, Sign, Spot, modes};
use linkage::error::NameKind;
use linkage::mechanisms::{BareFourBar, CouplerFourBar, FourBar, OffsetSliderCrank};
use linkage::prelude::*;
use std::f64::consts::{PI, TAU};

/// θ2 = 20°, as the reference script's driver (its f64 repr).
const DEG20: f64 = 0.3490658503988659;

/// The found modes are the reference's, one for one, each coordinate
/// within 1e-12 (relative to it for a length beyond 1; an angle up to
/// whole turns, though both are in [−π, π)); every mode is regular,
/// closes and is a fixed point of the runtime's Newton.
fn assert_modes<L: Linkage<M, F>, const M: usize, const F: usize>(
    name: &str,
    model: &L,
    found: &Modes<M, F>,
    reference: &[[f64; M]],
) {
    assert!(found.stable, "{name}: the search did not stabilise");
    assert!(
        found.dead_centres.is_empty(),
        "{name}: {:?}",
        found.dead_centres
    );
    assert_eq!(
        found.modes.len(),
        reference.len(),
        "{name}: {} modes, the reference {}: {:?}",
        found.modes.len(),
        reference.len(),
        found.modes.iter().map(|m| m.u).collect::<Vec<_>>()
    );
    let mut matched = vec![false; reference.len()];
    for mode in &found.modes {
        let k = reference
            .iter()
            .position(|r| (0..M).all(|j| (mode.u[j] - r[j]).abs() <= 1e-12 * r[j].abs().max(1.0)))
            .unwrap_or_else(|| panic!("{name}: mode {:?} is no reference root", mode.u));
        assert!(!matched[k], "{name}: two modes at reference root {k}");
        matched[k] = true;
        assert!(
            mode.residual <= 1e-12,
            "{name}: residual {:e}",
            mode.residual
        );
        assert!(mode.rcond > 1e-6, "{name}: rcond {:e}", mode.rcond);
        let solved = model
            .solve_position(&mode.u, &found.v, &Options::default())
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(
            solved.iterations <= 1,
            "{name}: {} iterations",
            solved.iterations
        );
        assert!((solved.u - mode.u).amax() <= 1e-13 * mode.u.amax().max(1.0));
        // The points are those of the pose.
        let points = model.point_positions(&mode.u, &found.v);
        assert_eq!(points.as_ref(), &mode.points[..], "{name}");
    }
}

/// The reference's worksheet four-bar at θ2 = 20°: (θ3, θ4).
const FOUR_BAR: [[f64; 2]; 2] = [
    [-1.4539395723946493940, 0.65820048345310620212],
    [1.2313431472543473290, -0.88079690859340826709],
];

#[test]
fn the_worksheet_four_bar_has_two_modes_one_of_them_the_worksheets() {
    let v = vector![DEG20];
    let found = modes(&FourBar::WORKSHEET, &v, &Search::default()).unwrap();
    assert_modes("four-bar", &FourBar::WORKSHEET, &found, &FOUR_BAR);
    assert_eq!(found.blocks.len(), 1);
    // Its sign is that of l3·l4·sin(θ4 − θ3), open before crossed.
    for mode in &found.modes {
        let expected = Sign::of((mode.u[1] - mode.u[0]).sin());
        assert_eq!(mode.signs, [expected]);
        assert_eq!(mode.determinant, expected);
    }
    assert_eq!(found.modes[0].signs, [Sign::Positive]);
    // The worksheet's own pose (θ3 = 70.55076547°) is mode 1.
    assert!((found.modes[1].u[0].to_degrees() - 70.550_765_47).abs() < 1e-8);
    // The same equations in the other ready four-bars.
    let bare = modes(&BareFourBar::WORKSHEET, &v, &Search::default()).unwrap();
    assert_modes("bare four-bar", &BareFourBar::WORKSHEET, &bare, &FOUR_BAR);
    let coupler = modes(&CouplerFourBar::WORKSHEET, &v, &Search::default()).unwrap();
    assert_modes(
        "coupler four-bar",
        &CouplerFourBar::WORKSHEET,
        &coupler,
        &FOUR_BAR,
    );
}

#[test]
fn a_four_bar_that_cannot_close_is_a_typed_error_not_a_dead_centre() {
    // B is at least 60 from D, the coupler and rocker reach 30: the
    // reference's polynomial has no real root.
    let short = FourBar {
        l1: 80.0,
        l2: 20.0,
        l3: 10.0,
        l4: 20.0,
    };
    let error = modes(&short, &vector![DEG20], &Search::default()).unwrap_err();
    let AssemblyError::NoAssembly {
        v, least_residual, ..
    } = &error
    else {
        panic!("{error:?}");
    };
    assert_eq!(v, &[DEG20]);
    // It misses by the gap (30 of the equations' size, about 4·(l2 + l3 + l4)).
    assert!(*least_residual > 0.05, "{least_residual}");
    let message = error.to_string();
    assert!(message.contains("cannot be assembled"), "{message}");
    assert!(!message.contains("dead centre"), "{message}");
    // And no mode to pick.
    let pick = short.assemble(&vector![DEG20], &Pick::Index(0));
    assert!(matches!(pick, Err(AssemblyError::NoAssembly { .. })));
}

#[test]
fn a_four_bar_exactly_at_its_dead_centre_is_one_dead_centre_not_two_modes() {
    // At θ2 = 0, |BD| = 60: with l3 + l4 = 60 the coupler and rocker lie
    // in line, with l4 − l3 = 60 folded onto each other; either way one
    // double root, θ3 = θ4 = 0 or θ3 = π, θ4 = 0.
    for (l4, theta3) in [(35.0, 0.0), (85.0, -PI)] {
        let folded = FourBar {
            l1: 80.0,
            l2: 20.0,
            l3: 25.0,
            l4,
        };
        let found = modes(&folded, &vector![0.0], &Search::default()).unwrap();
        assert!(found.modes.is_empty(), "{:?}", found.modes);
        assert_eq!(found.dead_centres.len(), 1, "{:?}", found.dead_centres);
        let dead = &found.dead_centres[0];
        let off = (dead.u - vector![theta3, 0.0]).map(|d| (d + PI).rem_euclid(TAU) - PI);
        assert!(off.amax() < 1e-6, "{:?}", dead.u);
        assert!(dead.rcond < 1e-6 && dead.residual < 1e-12);
        let error = found.pick(&Pick::Index(0)).unwrap_err();
        assert_eq!(error, AssemblyError::AtDeadCentre { dead_centres: 1 });
        assert!(error.to_string().contains("dead centre"));
    }
    // Folded onto each other it opens as the crank turns: two modes, one
    // each side.
    let folded = FourBar {
        l1: 80.0,
        l2: 20.0,
        l3: 25.0,
        l4: 85.0,
    };
    let near = modes(&folded, &vector![0.01], &Search::default()).unwrap();
    assert_eq!(near.modes.len(), 2);
    assert_ne!(near.modes[0].signs, near.modes[1].signs);
}

#[test]
fn slider_cranks_have_two_modes() {
    // (θ3, s) at θ2 = 1.
    let reference = [
        [-2.9805294436775284850, -0.17039635205113197426],
        [-0.16106320991226475346, 0.22442658263794594900],
    ];
    let v = vector![1.0];
    let found = modes(&SLIDER_CRANK, &v, &Search::default()).unwrap();
    assert_modes("slider-crank", &SLIDER_CRANK, &found, &reference);
    assert_eq!(found.angle, [true, false]);
    let ready = OffsetSliderCrank {
        r: 0.05,
        l: 0.2,
        e: 0.01,
    };
    let found = modes(&ready, &v, &Search::default()).unwrap();
    assert_modes("offset slider-crank", &ready, &found, &reference);
    // (θ2, θ3) driven by the slider at s = 0.2.
    let reference = [
        [-1.3906325337380474190, 0.30045367545163727190],
        [1.4905493251819329384, -0.20053688400775175254],
    ];
    let found = modes(&SLIDER_DRIVEN, &vector![0.2], &Search::default()).unwrap();
    assert_modes("slider-driven", &SLIDER_DRIVEN, &found, &reference);
}

#[test]
fn the_boom_the_five_bar_and_the_coupler_body_have_two_modes() {
    // (θ, φ) at the actuator length 1.
    let reference = [
        [-1.9616171804461023024, -2.4669776907302596208],
        [0.67461496285953361762, 1.1799754731436909361],
    ];
    let found = modes(&BOOM, &vector![1.0], &Search::default()).unwrap();
    assert_modes("boom", &BOOM, &found, &reference);
    // (θ3, θ4) at θ2 = 1, θ5 = 2: two drivers.
    let reference = [
        [-1.2715158398451742310, -1.7907992789918118109],
        [1.3507933745979814276, 1.8700768137446190075],
    ];
    let found = modes(&FIVE_BAR, &vector![1.0, 2.0], &Search::default()).unwrap();
    assert_modes("five-bar", &FIVE_BAR, &found, &reference);
    // (x_p, y_p, θ3, θ4) at θ2 = 0.5: two lengths, one block of four.
    let coupler = Coupler {
        xa: 0.0,
        ya: 0.0,
        xd: 80.0,
        yd: 0.0,
        l2: 20.0,
        l4: 70.0,
        bx: -25.0,
        by: -10.0,
        cx: 25.0,
        cy: -10.0,
    };
    let reference = [
        [
            18.265829790429229513,
            36.504861731955553446,
            1.1637629131153420196,
            2.2260279805889335405,
        ],
        [
            30.053054588083288164,
            -14.259233655297581936,
            -1.4684693777635047215,
            -2.5307344452370962424,
        ],
    ];
    let found = modes(&coupler, &vector![0.5], &Search::default()).unwrap();
    assert_modes("coupler body", &coupler, &found, &reference);
    assert_eq!(found.angle, [false, false, true, true]);
}

#[test]
fn the_four_bar_with_a_dyad_has_two_modes_its_dyad_reaching_from_one_branch_only() {
    // (θ3, θ4, θ5, θ6) at θ2 = 20°: from the worksheet's branch only.
    let reference = [
        [
            1.2313431472543473290,
            -0.88079690859340826709,
            0.42336132471983455924,
            -0.39382640390013252071,
        ],
        [
            1.2313431472543473290,
            -0.88079690859340826709,
            2.3338376358602633341,
            -3.1321599426993560629,
        ],
    ];
    let found = modes(&SIX_BAR, &vector![DEG20], &Search::default()).unwrap();
    assert_modes("six-bar", &SIX_BAR, &found, &reference);
    assert_eq!(found.blocks.len(), 2);
}

#[test]
fn the_watt_six_bar_has_four_modes_named_by_the_signs_of_its_two_loops() {
    let reference = [
        [
            -1.4539395723946493940,
            0.65820048345310620212,
            0.45612293717047425700,
            -3.0801226716083823173,
        ],
        [
            -1.4539395723946493940,
            0.65820048345310620212,
            2.3495369214313082551,
            -0.39740277696942164754,
        ],
        [
            1.2313431472543473290,
            -0.88079690859340826709,
            1.0873442088643219003,
            2.6917168478151573515,
        ],
        [
            1.2313431472543473290,
            -0.88079690859340826709,
            2.5042400995406155648,
            0.89986746058978011359,
        ],
    ];
    let found = modes(&WATT_SIX_BAR, &vector![DEG20], &Search::default()).unwrap();
    assert_modes("Watt six-bar", &WATT_SIX_BAR, &found, &reference);
    // The four-bar loop, then the loop hanging from its rocker.
    assert_eq!(found.blocks.len(), 2);
    assert_eq!(found.blocks[0].coordinates, [0, 1]);
    assert_eq!(found.blocks[1].coordinates, [2, 3]);
    // Each pair of signs once, in order: ++, +−, −+, −−.
    let signs: Vec<Vec<Sign>> = found.modes.iter().map(|m| m.signs.clone()).collect();
    use Sign::{Negative as N, Positive as P};
    assert_eq!(signs, [[P, P], [P, N], [N, P], [N, N]]);
    // det Ψ_u is the product of the loops' determinants here (no
    // permutation between the blocks).
    for mode in &found.modes {
        let product = if mode.signs[0] == mode.signs[1] { P } else { N };
        assert_eq!(mode.determinant, product);
    }
}

/// The Stephenson III six-bar's six assemblies at θ2 = atan2(4, 3):
/// (θ3, θ4, θ5, θ6).
const STEPHENSON: [[f64; 4]; 6] = [
    [
        -2.1254695727052804747,
        -1.7508310771832375296,
        -0.53065341091318211037,
        -0.78872754266138631577,
    ],
    [
        -1.3304563156209455874,
        2.5988584009109152086,
        1.9487948232606883348,
        -1.8769259377490629045,
    ],
    [
        -1.0015300064691851859,
        -0.30489800802092820724,
        0.096382955077895572324,
        -0.45981384688261264952,
    ],
    [
        -0.42562952655235839240,
        2.1960620253655833792,
        2.3195321555367621520,
        -1.5386280442914980985,
    ],
    [
        1.5994998683119215875,
        1.1872400022202454733,
        -0.33062366575832677692,
        0.24343916598979434021,
    ],
    [
        2.0197968388325758795,
        3.0618662621642103137,
        -1.5125388564582611332,
        -0.62066990108012689763,
    ],
];

#[test]
fn the_stephenson_three_six_bar_has_six_modes_in_one_block() {
    let v = vector![4f64.atan2(3.0)];
    let found = modes(&STEPHENSON_THREE, &v, &Search::default()).unwrap();
    assert_modes("Stephenson III", &STEPHENSON_THREE, &found, &STEPHENSON);
    assert_eq!(found.blocks.len(), 1);
    assert_eq!(found.blocks[0].coordinates, [0, 1, 2, 3]);
    // Six modes, two signs: the sign alone does not name them, a pick does.
    let positive = found
        .modes
        .iter()
        .filter(|m| m.signs == [Sign::Positive])
        .count();
    assert!(positive > 0 && positive < 6);
    for (k, mode) in found.modes.iter().enumerate() {
        let near = mode.u + SVector::from_element(0.05);
        assert_eq!(found.index_of(&Pick::nearest(near)), Ok(k));
    }
}

#[test]
fn the_stephenson_three_six_bar_has_four_modes_at_another_crank_angle() {
    // (θ3, θ4, θ5, θ6) at θ2 = atan2(5, 12).
    let reference = [
        [
            -1.3369731493182233983,
            2.7250363005515211177,
            2.0487046845695050207,
            -1.9006751686518309950,
        ],
        [
            -0.14983946298595432555,
            2.2874957776072330205,
            2.5921869165725337252,
            -1.4393442775651966491,
        ],
        [
            1.6138638326791011673,
            1.1325665398292784532,
            -0.29083252720167064237,
            0.34991223213504407791,
        ],
        [
            1.8459590470751868728,
            3.0628565524887071664,
            -1.6906333778518701463,
            -0.62758274613839479408,
        ],
    ];
    let v = vector![5f64.atan2(12.0)];
    let found = modes(&STEPHENSON_THREE, &v, &Search::default()).unwrap();
    assert_modes(
        "Stephenson III (four)",
        &STEPHENSON_THREE,
        &found,
        &reference,
    );
}

#[test]
fn the_search_is_deterministic_and_its_order_is_by_sign_then_coordinates() {
    let v = vector![4f64.atan2(3.0)];
    let a = modes(&STEPHENSON_THREE, &v, &Search::default()).unwrap();
    let b = modes(&STEPHENSON_THREE, &v, &Search::default()).unwrap();
    assert_eq!(a, b);
    for pair in a.modes.windows(2) {
        let by_sign = pair[0].signs.cmp(&pair[1].signs);
        assert!(by_sign.is_lt() || (by_sign.is_eq() && pair[0].u[0] < pair[1].u[0]));
    }
}

#[test]
fn picks_by_index_side_and_sketch() {
    let bar = FourBar::WORKSHEET;
    let v = vector![DEG20];
    let found = modes(&bar, &v, &Search::default()).unwrap();
    let d = vector![80.0, 0.0];
    // C left of B → D is the worksheet's mode (1), right of it the other.
    let left = found.index_of(&Pick::left_of("C", "B", d)).unwrap();
    let right = found.index_of(&Pick::right_of("C", "B", d)).unwrap();
    assert_eq!((left, right), (1, 0));
    // The sketch: C roughly where the worksheet draws it.
    let sketch = Pick::nearest_points(&[("C", vector![35.0, 65.0])]);
    assert_eq!(found.index_of(&sketch), Ok(1));
    // Rough coordinates: 60° and −60°.
    let rough = Pick::nearest(vector![60f64.to_radians(), -60f64.to_radians()]);
    assert_eq!(found.index_of(&rough), Ok(1));
    // ... up to whole turns.
    let turned = Pick::nearest(vector![60f64.to_radians() + TAU, -60f64.to_radians() - TAU]);
    assert_eq!(found.index_of(&turned), Ok(1));
    assert_eq!(found.pick(&Pick::Index(0)), Ok(&found.modes[0]));
    // Through the extension trait, in one call.
    let mode = bar.assemble(&v, &Pick::left_of("C", "B", d)).unwrap();
    assert_eq!(mode, found.modes[1]);
}

#[test]
fn picks_that_fail_say_why() {
    let found = modes(&FourBar::WORKSHEET, &vector![DEG20], &Search::default()).unwrap();
    let d = vector![80.0, 0.0];
    assert_eq!(
        found.index_of(&Pick::Index(2)),
        Err(AssemblyError::IndexOutOfRange { index: 2, modes: 2 })
    );
    // Both modes put C left of the line from A far down to the right.
    let origin = Spot::At(vector![0.0, 0.0]);
    let ambiguous = Pick::left_of("C", origin.clone(), vector![100.0, -1000.0]);
    match found.index_of(&ambiguous) {
        Err(AssemblyError::Ambiguous { modes, pick }) => {
            assert_eq!(modes, [0, 1]);
            assert_eq!(pick, "C left of (0, 0) → (100, -1000)");
        }
        other => panic!("{other:?}"),
    }
    let none = Pick::right_of("C", origin, vector![100.0, -1000.0]);
    assert!(matches!(
        found.index_of(&none),
        Err(AssemblyError::NoMatch { .. })
    ));
    // A point the four-bar does not have.
    match found.index_of(&Pick::left_of("Q", "B", d)) {
        Err(AssemblyError::UnknownName(name)) => {
            assert_eq!(name.kind, NameKind::Point);
            assert_eq!(name.name, "Q");
            assert_eq!(name.known, "B, C, G2, G3, G4");
        }
        other => panic!("{other:?}"),
    }
    let sketch = Pick::nearest_points(&[("D", d)]);
    assert!(matches!(
        found.index_of(&sketch),
        Err(AssemblyError::UnknownName(_))
    ));
    // Equally near both: the point midway between the two C's.
    let c = |k: usize| found.modes[k].points[FourBar::C];
    let midway = Pick::nearest_points(&[("C", (c(0) + c(1)) / 2.0)]);
    assert!(matches!(
        found.index_of(&midway),
        Err(AssemblyError::Ambiguous { .. })
    ));
}

#[test]
fn bad_input_and_settings_are_typed_errors() {
    let bar = FourBar::WORKSHEET;
    let error = modes(&bar, &vector![f64::NAN], &Search::default()).unwrap_err();
    assert!(matches!(
        error,
        AssemblyError::Input(Error::NonFiniteInput { argument: "v", .. })
    ));
    for search in [
        Search {
            first_cells: 0,
            ..Search::default()
        },
        Search {
            confirmations: 0,
            ..Search::default()
        },
        Search {
            max_cells: 2,
            ..Search::default()
        },
        Search {
            lengths: Lengths::Within(-1.0),
            ..Search::default()
        },
        Search {
            lengths: Lengths::Bounds(vec![(0.0, 1.0)]),
            ..Search::default()
        },
    ] {
        let error = modes(&bar, &vector![DEG20], &search).unwrap_err();
        assert!(
            matches!(error, AssemblyError::Input(Error::InvalidInput { .. })),
            "{search:?}: {error:?}"
        );
    }
    // A length's bounds must be ordered; an angle's are not read.
    let reversed = Search {
        lengths: Lengths::Bounds(vec![(0.0, 0.0), (1.0, -1.0)]),
        ..Search::default()
    };
    let error = modes(&SLIDER_CRANK, &vector![1.0], &reversed).unwrap_err();
    assert!(matches!(
        error,
        AssemblyError::Input(Error::InvalidInput { .. })
    ));
}

#[test]
fn the_lengths_box_is_the_mechanisms_scale_or_the_users() {
    let v = vector![1.0];
    let found = modes(&SLIDER_CRANK, &v, &Search::default()).unwrap();
    // Every assembly |s| ≤ r + l = 0.25 lies inside the box.
    assert!(found.upper[1] >= 0.25 && found.lower[1] <= -0.25);
    assert_eq!((found.lower[0], found.upper[0]), (-PI, PI));
    // The user's box: the slider to the right of the pivot.
    let right = Search {
        lengths: Lengths::Bounds(vec![(0.0, 0.0), (0.0, 0.3)]),
        ..Search::default()
    };
    let found = modes(&SLIDER_CRANK, &v, &right).unwrap();
    assert_eq!((found.lower[1], found.upper[1]), (0.0, 0.3));
    assert!(found.modes.iter().any(|m| m.u[1] > 0.0));
    let found = modes(
        &SLIDER_CRANK,
        &v,
        &Search {
            lengths: Lengths::Within(0.5),
            ..Search::default()
        },
    )
    .unwrap();
    assert_eq!((found.lower[1], found.upper[1]), (-0.5, 0.5));
    assert_eq!(found.modes.len(), 2);
}

#[test]
fn a_search_cut_short_says_so() {
    // The first grid (3 × 3) runs; its refinements (16 cells) may not.
    let short = Search {
        max_cells: 9,
        ..Search::default()
    };
    let found = modes(&FourBar::WORKSHEET, &vector![DEG20], &short).unwrap();
    assert!(!found.stable);
    assert_eq!(found.modes.len(), 2);
    let too_short = FourBar {
        l1: 80.0,
        l2: 20.0,
        l3: 10.0,
        l4: 20.0,
    };
    let error = modes(&too_short, &vector![DEG20], &short).unwrap_err();
    assert!(matches!(
        error,
        AssemblyError::NoAssembly { stable: false, .. }
    ));
    let message = error.to_string();
    assert!(message.contains("Search::max_cells"), "{message}");
    assert!(!message.contains("cannot be assembled"), "{message}");
}

#[test]
fn newton_from_a_bad_guess_points_to_the_search() {
    // From zeros the four-bar's Ψ_u is singular (every link along x): the
    // message says the guess may be what is wrong.
    let error = FourBar::WORKSHEET
        .solve_position(&vector![0.0, 0.0], &vector![DEG20], &Options::default())
        .unwrap_err();
    assert!(matches!(error, Error::Singular { .. }), "{error:?}");
    let message = error.to_string();
    assert!(message.contains("linkage::assembly"), "{message}");
}
