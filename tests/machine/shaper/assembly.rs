//! The shaping machine assembled without a guess: its slider on the rocker
//! gives two modes, s·(cos φ3, sin φ3) = A − C with s = ±|AC|, and the ram
//! follows the rocker (x_d = l_CD cos φ3); the course project's is the one
//! with the rocker upward, its closed form.

use crate::machine::{COURSE_PROJECT, synthesize};
use linkage::assembly::{Pick, Search, modes};
use linkage::prelude::*;
use std::f64::consts::PI;

#[test]
fn the_shaper_has_two_modes_the_course_projects_among_them() {
    let shaper = synthesize(&COURSE_PROJECT).unwrap();
    let phi = shaper.analysed_position();
    let v = vector![phi];
    let found = modes(&shaper, &v, &Search::default()).unwrap();
    assert!(found.stable && found.dead_centres.is_empty());
    assert_eq!(found.modes.len(), 2);
    // The rocker and its slider, then the ram: two blocks.
    assert_eq!(found.blocks.len(), 2);
    assert_eq!(found.blocks[1].coordinates, [2]);
    assert_eq!(found.angle, [true, false, false]);
    let phi3 = shaper.closed_form_phi3(phi);
    let course = Pick::nearest(vector![phi3, 0.0, 0.0]);
    let ours = found.pick(&course).unwrap();
    let guessed = shaper
        .solve_position(&shaper.guess(), &v, &Options::default())
        .unwrap();
    assert!(
        (ours.u - guessed.u).amax() < 1e-13,
        "{:?} {:?}",
        ours.u,
        guessed.u
    );
    assert!((ours.u[2] - shaper.l_cd * phi3.cos()).abs() < 1e-13);
    // The other: the rocker turned half a turn, the slider behind C.
    let other = &found.modes[1 - found.index_of(&course).unwrap()];
    let turned = (other.u[0] - phi3 - PI + PI).rem_euclid(2.0 * PI) - PI;
    assert!(turned.abs() < 1e-13, "{:?}", other.u);
    assert!((other.u[1] + ours.u[1]).abs() < 1e-13);
    assert!((other.u[2] + ours.u[2]).abs() < 1e-13);
}
