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

// The same mechanisms as the tests' (one definition of each).
#[path = "../tests/models/stephenson_three.rs"]
mod stephenson_three;
#[path = "../tests/models/watt_six_bar.rs"]
mod watt_six_bar;
use stephenson_three::STEPHENSON_THREE;
use watt_six_bar::WATT_SIX_BAR;

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
    let watt = WATT_SIX_BAR;
    report("a Watt six-bar", &watt, 20f64.to_radians(), 101);
    let stephenson = STEPHENSON_THREE;
    report("a Stephenson III six-bar", &stephenson, 4f64.atan2(3.0), 21);
}
