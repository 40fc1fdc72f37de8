//! Assembly without a guess: every assembly mode of the Maple worksheet's
//! four-bar, a Watt six-bar and a Stephenson III six-bar at one crank
//! angle, with their branch signs, and the time the search takes.
//!
//! ```sh
//! cargo run --release --example assembly
//! ```

use linkage::assembly::{Modes, Pick, Search, modes};
use linkage::mechanisms::FourBar;
use linkage::prelude::*;
use std::time::Instant;

/// A Watt six-bar: the worksheet's four-bar, and a second loop from E,
/// rigid with the rocker (|DE| = le at θ4 + β), through F to the ground
/// pivot G.
#[linkage::linkage(
    u = [theta3, theta4, theta5, theta6],
    v = [theta2],
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
        l1 + le * (theta4 + beta).cos() + l5 * theta5.cos() + l6 * theta6.cos() - gx,
        le * (theta4 + beta).sin() + l5 * theta5.sin() + l6 * theta6.sin() - gy,
    ],
)]
pub struct WattSixBar {
    pub l1: f64,
    pub l2: f64,
    pub l3: f64,
    pub l4: f64,
    pub le: f64,
    pub beta: f64,
    pub l5: f64,
    pub l6: f64,
    pub gx: f64,
    pub gy: f64,
}

/// A Stephenson III six-bar: the crank AB carries the ternary link BCE,
/// the ternary link DFG turns about D, and the links CF and EG join them.
/// Its crank is in no four-bar loop: both loops close together.
#[linkage::linkage(
    u = [theta3, theta4, theta5, theta6],
    v = [theta2],
    points = [
        B = (l2 * theta2.cos(), l2 * theta2.sin()),
        C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
        E = (
            B.x + ex * theta3.cos() - ey * theta3.sin(),
            B.y + ex * theta3.sin() + ey * theta3.cos()
        ),
        F = (dx + l4 * theta4.cos(), dy + l4 * theta4.sin()),
        G = (
            dx + gx * theta4.cos() - gy * theta4.sin(),
            dy + gx * theta4.sin() + gy * theta4.cos()
        ),
    ],
    closure = [
        C.x + l5 * theta5.cos() - F.x,
        C.y + l5 * theta5.sin() - F.y,
        E.x + l6 * theta6.cos() - G.x,
        E.y + l6 * theta6.sin() - G.y,
    ],
)]
pub struct StephensonThree {
    pub l2: f64,
    pub l3: f64,
    pub ex: f64,
    pub ey: f64,
    pub dx: f64,
    pub dy: f64,
    pub l4: f64,
    pub gx: f64,
    pub gy: f64,
    pub l5: f64,
    pub l6: f64,
}

/// The modes, one a line, and the search's cost: the median time of
/// `repeats` searches.
fn report<L: Linkage<M, 1>, const M: usize>(name: &str, model: &L, theta2: f64, repeats: usize) {
    let v = vector![theta2];
    let found: Modes<M, 1> = modes(model, &v, &Search::default()).expect("it assembles");
    let mut times: Vec<f64> = (0..repeats)
        .map(|_| {
            let start = Instant::now();
            let again = modes(model, &v, &Search::default()).expect("it assembles");
            let elapsed = start.elapsed().as_secs_f64();
            assert_eq!(again, found);
            elapsed
        })
        .collect();
    times.sort_by(f64::total_cmp);
    let blocks: Vec<usize> = found.blocks.iter().map(|b| b.equations.len()).collect();
    println!(
        "{name} at θ2 = {:.4}°: {} modes, blocks of {blocks:?}, {} Newton runs, {:.3} ms (median of {repeats})",
        theta2.to_degrees(),
        found.modes.len(),
        found.runs,
        1e3 * times[repeats / 2],
    );
    for (k, mode) in found.modes.iter().enumerate() {
        let degrees: Vec<String> = mode
            .u
            .iter()
            .map(|x| format!("{:9.4}°", x.to_degrees()))
            .collect();
        let signs: String = mode.signs.iter().map(|s| s.to_string()).collect();
        println!(
            "  mode {k}: u = [{}]  signs {signs}  rcond {:.2e}",
            degrees.join(", "),
            mode.rcond
        );
    }
}

fn main() {
    let bar = FourBar::WORKSHEET;
    report(
        "the Maple worksheet's four-bar",
        &bar,
        20f64.to_radians(),
        101,
    );
    // The worksheet's own pose, picked by its joint C's side of B → D.
    let theta2 = vector![20f64.to_radians()];
    let found = modes(&bar, &theta2, &Search::default()).expect("it assembles");
    let pick = Pick::left_of("C", "B", vector![bar.l1, 0.0]);
    let mode = found.pick(&pick).expect("one mode");
    println!(
        "  {pick}: θ3 = {:.8}° (the worksheet: 70.55076545°)",
        mode.u[0].to_degrees()
    );
    let watt = WattSixBar {
        l1: 80.0,
        l2: 20.0,
        l3: 50.0,
        l4: 70.0,
        le: 40.0,
        beta: 0.5,
        l5: 60.0,
        l6: 50.0,
        gx: 100.0,
        gy: 60.0,
    };
    report("a Watt six-bar", &watt, 20f64.to_radians(), 101);
    let stephenson = StephensonThree {
        l2: 10.0,
        l3: 60.0,
        ex: -7.0,
        ey: 30.0,
        dx: 49.0,
        dy: -16.0,
        l4: 65.0,
        gx: 20.0,
        gy: 29.0,
        l5: 73.0,
        l6: 55.0,
    };
    report("a Stephenson III six-bar", &stephenson, 4f64.atan2(3.0), 21);
}
