//! What the campaigns over mechanism texts and files found, each kept as
//! the smallest text that shows it.

use linkage::mechanism::Mechanism;

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
