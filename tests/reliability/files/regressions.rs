//! What the campaigns over mechanism texts and files found, each kept as
//! the smallest text that shows it.

use linkage::assembly::{Assemble, AssemblyError, Pick, Search, modes};
use linkage::mechanism::Mechanism;
use linkage::prelude::*;
use linkage::{Error, Stage};

/// The mechanism of `text` with parameters `l0` = 178.67 and `l1` = 2.17.
fn mechanism(text: &str) -> Mechanism {
    Mechanism::from_text("Found", text, &[("l0", 178.67), ("l1", 2.17)]).unwrap()
}

/// A coordinate whose sine and cosine are written only of a sum,
/// `(q3 + 0.5).cos()`, was searched as a length: a root every turn of a
/// box ±161 wide and 16 boxes beyond, 1635 modes in 12 s, and a
/// campaign's case of four coordinates never ended. It is an angle.
#[test]
fn a_coordinate_turning_inside_a_sum_is_an_angle() {
    let text = "u = [q3, q4], v = [t],
        closure = [t + l1 * (q3 + 0.5).cos() + q4 - l0, l1 * (q3 + 0.5).sin() - 0.5]";
    let model = mechanism(text).fixed::<2, 1>().unwrap();
    let found = modes(&model, &vector![2.72], &Search::default()).unwrap();
    assert_eq!(found.angle, [true, false]);
    assert_eq!(found.modes.len(), 2);
    assert!(found.stable);
}

/// A coordinate that turns but is not 2π-periodic, `(q / 2).sin()`, is
/// searched as a length, with a root every 4π: the search keeps at most
/// 64, and says it was cut short.
#[test]
fn a_search_with_a_root_every_turn_is_cut_short() {
    let text =
        "u = [q, s], v = [t], closure = [s - l1 * (q * 0.5).cos() - l0 - t, (q * 0.5).sin() - 0.3]";
    let model = mechanism(text).fixed::<2, 1>().unwrap();
    let found = modes(&model, &vector![0.0], &Search::default()).unwrap();
    assert_eq!(found.angle, [false, false]);
    assert!(!found.stable);
    assert!(found.modes.len() <= 64, "{}", found.modes.len());
}

/// An assembly whose named point is outside its domain there
/// (`(x - 2.0).sqrt()` at x = 1) came back `Ok` with NaN in its points;
/// the analysis of the same pose said `NonFiniteValue`. Now the search
/// says so too.
#[test]
fn an_assembly_whose_point_is_not_finite_is_an_error() {
    let text = "u = [x], v = [t], points = [P = ((x - 2.0).sqrt(), x)], closure = [x - t]";
    let model = Mechanism::from_text("Found", text, &[])
        .unwrap()
        .fixed::<1, 1>()
        .unwrap();
    let error = model.assemble(&vector![1.0], &Pick::Index(0)).unwrap_err();
    assert_eq!(
        error,
        AssemblyError::Input(Error::NonFiniteValue {
            stage: Stage::Points,
            quantity: "P"
        })
    );
    // Where the point is finite, the same mechanism assembles.
    let mode = model.assemble(&vector![3.0], &Pick::Index(0)).unwrap();
    assert_eq!(mode.points[0].x, 1.0);
}

/// A power of a sum nested ten deep, `((x.sin() + y).powi(2)).powi(2)…`:
/// within every limit of the text, but the proof that the two
/// acceleration methods agree multiplied it out term by term, 7 s for
/// one mechanism. The proof now has a budget, and is abandoned
/// (`methods_agree` is `None`: too large to compare).
#[test]
fn a_proof_too_long_to_do_is_abandoned() {
    let power = format!("{}x.sin() + y{}", "(".repeat(10), ").powi(2)".repeat(10));
    let text = format!("u = [x, y], v = [t], closure = [l0 * x.cos() + y.cos() - t, {power}]");
    let started = std::time::Instant::now();
    let mechanism = Mechanism::from_text("Found", &text, &[("l0", 2.0)]).unwrap();
    assert_eq!(mechanism.methods_agree(), None);
    eprintln!("built in {:.2} s", started.elapsed().as_secs_f64());
}

/// Ten coordinates coupled in one block: the first grid, 3¹⁰ = 59 049
/// Newton runs, ran whatever its size (1.4 s; 3¹⁶, for the largest
/// mechanisms the tool takes, hours). It is now as fine as
/// `Search::max_cells` allows, and the search says it is not stable.
#[test]
fn a_large_block_starts_on_a_grid_within_the_limit() {
    const M: usize = 10;
    let u: Vec<String> = (0..M).map(|k| format!("x{k}")).collect();
    let closure: Vec<String> = (0..M)
        .map(|k| format!("x{k} + 0.5 * x{}.sin() - t", (k + 1) % M))
        .collect();
    let text = format!(
        "u = [{}], v = [t], closure = [{}]",
        u.join(", "),
        closure.join(", ")
    );
    let model = Mechanism::from_text("Found", &text, &[])
        .unwrap()
        .fixed::<M, 1>()
        .unwrap();
    let found = modes(&model, &vector![0.3], &Search::default()).unwrap();
    assert_eq!(found.blocks.len(), 1);
    assert!(found.runs <= Search::default().max_cells, "{}", found.runs);
    assert!(!found.stable);
    assert_eq!(found.modes.len(), 1);
}

/// A link of length 0 (Jansen's leg with j = 0): its angle moves no
/// equation, Ψ_u is singular everywhere, and the search ran every grid of
/// the six coordinates together to its largest, 1.2 s, to find nothing.
/// Now it says so at once.
#[test]
fn a_link_of_length_zero_is_singular_everywhere() {
    let text = "u = [theta3, theta4], v = [theta2],
        closure = [
            l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
            l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
        ]";
    let parameters = [("l1", 80.0), ("l2", 20.0), ("l3", 0.0), ("l4", 70.0)];
    let model = Mechanism::from_text("Found", text, &parameters)
        .unwrap()
        .fixed::<2, 1>()
        .unwrap();
    let error = modes(&model, &vector![0.3], &Search::default()).unwrap_err();
    assert_eq!(error, AssemblyError::SingularEverywhere { idle: vec![0] });
    assert!(
        error
            .to_string()
            .contains("no equation moves the coordinates [0]")
    );
}
