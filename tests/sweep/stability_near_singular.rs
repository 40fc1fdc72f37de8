//! Near singular poses, each method against the 50-digit reference: the
//! library's API returns a correct answer or a typed error, never a wrong
//! `Ok`; the other methods' behaviour is recorded. (The same study draws
//! the charts of `cargo run --release --example stability`.)

#[path = "../../examples/stability/study.rs"]
mod study;

use study::{Case, Method, Row, run};

/// What "correct" means here: positions to 1e-6 rad, the analogs to 1e-6 of
/// their size — the accuracy the library promises by default.
const CORRECT: f64 = 1e-6;

fn correct(r: &Row) -> bool {
    r.position <= CORRECT && r.velocity <= CORRECT && r.acceleration <= CORRECT
}

#[test]
fn the_library_returns_a_correct_answer_or_a_typed_error() {
    for case in [Case::Limit, Case::Branch] {
        let rows = run(case);
        let library: Vec<&Row> = rows
            .iter()
            .filter(|r| r.method == Method::Generated)
            .collect();
        assert_eq!(library.len(), 49);
        for r in &library {
            match &r.error {
                None => assert!(
                    correct(r),
                    "{}: a wrong Ok at δ = {:e}: {r:?}",
                    case.name(),
                    r.delta
                ),
                Some(message) => assert!(
                    message.starts_with("Ψ_u is singular"),
                    "{}: at δ = {:e} the error is not the singular-pose one: {message}",
                    case.name(),
                    r.delta
                ),
            }
        }
        // It answers as close as the accuracy allows, not only far away:
        // correct answers down to δ = 1e-8 at the limit position (where the
        // velocities are 10⁴ times their usual size), 2e-3 at the branch point.
        let closest = library
            .iter()
            .filter(|r| r.error.is_none())
            .map(|r| r.delta)
            .fold(f64::INFINITY, f64::min);
        let expected = match case {
            Case::Limit => 2e-8,
            Case::Branch => 2e-3,
        };
        assert!(
            closest <= expected,
            "{}: answers only down to δ = {closest:e}",
            case.name()
        );
        eprintln!(
            "{}: correct answers down to δ = {closest:.1e}, typed errors below",
            case.name()
        );
    }
}

/// Without the conditioning check the same generated code, and the closed
/// form too, return garbage near the branch point: accelerations off by
/// more than their own size.
#[test]
fn without_the_check_near_the_branch_point_answers_are_garbage() {
    let rows = run(Case::Branch);
    for method in [Method::Unguarded, Method::ClosedForm] {
        let worst = rows
            .iter()
            .filter(|r| r.method == method && r.error.is_none())
            .map(|r| r.acceleration)
            .fold(0.0, f64::max);
        assert!(
            worst > 1.0,
            "{}: worst acceleration error {worst:e}",
            method.name()
        );
        eprintln!(
            "{}: worst acceleration error {worst:.1e} (returned as if fine)",
            method.name()
        );
    }
}

/// Newton stays quadratic up to a limit position: a handful of iterations
/// from a continuation-like start, whatever the source of the Jacobian. At a
/// branch point the root itself is singular and Newton slows to linear
/// convergence: the count grows as δ shrinks (recorded in the chart), but the
/// library's answer there is a typed error anyway.
#[test]
fn newton_needs_few_iterations_near_a_limit_position() {
    for r in run(Case::Limit) {
        if let (Some(iterations), Method::Generated | Method::Dual | Method::Unguarded) =
            (r.iterations, r.method)
        {
            assert!(
                iterations <= 6,
                "{}: {iterations} iterations at δ = {:e}",
                r.method.name(),
                r.delta
            );
        }
    }
    let branch = run(Case::Branch);
    let unguarded = |far: bool| {
        branch
            .iter()
            .filter(|r| r.method == Method::Unguarded && (r.delta > 1e-3) == far)
            .filter_map(|r| r.iterations)
            .max()
            .unwrap_or(0)
    };
    assert!(unguarded(true) <= 6 && unguarded(false) > unguarded(true));
    eprintln!(
        "branch point: Newton takes at most {} iterations for δ > 1e-3, up to {} closer",
        unguarded(true),
        unguarded(false)
    );
}

/// Methods A and B near the boom's limit position: whatever the condition
/// number of Ψ_u, they agree to rounding with each other, while both lose
/// accuracy against the reference together, as ε·κ².
#[test]
fn methods_a_and_b_degrade_together() {
    let rows = study::methods_near_limit();
    assert!(rows.len() >= 45);
    for r in &rows {
        assert!(r.a_minus_b <= 1e-15 && r.fused_minus_b <= 1e-15, "{r:?}");
        let (low, high) = (r.error_a.min(r.error_b), r.error_a.max(r.error_b));
        assert!(
            high <= 2.0 * low + 1e-15,
            "A and B lose accuracy together: {r:?}"
        );
        assert!(
            r.error_a <= 1e2 * f64::EPSILON * r.condition.powi(2),
            "{r:?}"
        );
        if let Some(library) = r.library {
            assert!(library <= CORRECT, "the library's Ok: {r:?}");
        }
    }
    let worst = rows.iter().map(|r| r.error_a).fold(0.0, f64::max);
    assert!(
        worst > 1e-5,
        "near κ ~ 1e7 both methods are off by {worst:e}"
    );
}
