//! Where each method breaks: approaching a limit position (non-Grashof
//! four-bar) and a branch point (change-point four-bar), the errors of the
//! library, of the same code without its conditioning check, of num-dual
//! and finite-difference Jacobians and of the closed form, against the
//! 50-digit reference; Newton's iterations; and methods A and B against the
//! condition number of Ψ_u (actuator-driven boom).
//!
//! Run with `cargo run --release --example stability`; it prints the tables
//! and writes the charts to `out/stability/` (`stability_limit.svg`,
//! `stability_branch.svg`, `stability_iterations.svg`,
//! `stability_methods.svg`).

mod charts;
#[path = "../support/output.rs"]
mod output;
mod study;

use study::{Case, Row};

fn print_table(case: Case, rows: &[Row]) {
    println!("\n{}", case.name());
    println!(
        "{:>9} {:>9}  {:<34} {:>4} {:>9} {:>9} {:>9}  outcome",
        "δ [rad]", "κ(Ψ_u)", "method", "it", "θ err", "ω err", "α err"
    );
    for r in rows {
        let outcome = match (
            &r.error,
            r.position.max(r.velocity).max(r.acceleration) <= 1e-6,
        ) {
            (Some(e), _) => format!("typed error: {}", e.split(':').next().unwrap_or(e)),
            (None, true) => "ok".to_owned(),
            (None, false) => "ok, but off by more than 1e-6".to_owned(),
        };
        println!(
            "{:9.2e} {:9.2e}  {:<34} {:>4} {:9.1e} {:9.1e} {:9.1e}  {outcome}",
            r.delta,
            r.condition,
            r.method.name(),
            r.iterations.map_or("—".to_owned(), |i| i.to_string()),
            r.position,
            r.velocity,
            r.acceleration
        );
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let figures = output::folder("stability")?;
    let limit = study::run(Case::Limit);
    let branch = study::run(Case::Branch);
    print_table(Case::Limit, &limit);
    print_table(Case::Branch, &branch);
    let write = |name: &str, svg: String| std::fs::write(figures.join(name), svg);
    write(
        "stability_limit.svg",
        charts::error_chart(Case::Limit, &limit)?,
    )?;
    write(
        "stability_branch.svg",
        charts::error_chart(Case::Branch, &branch)?,
    )?;
    write(
        "stability_iterations.svg",
        charts::iterations_chart(&limit, &branch)?,
    )?;
    let methods = study::methods_near_limit();
    println!("\nboom near full extension: methods A and B");
    println!(
        "{:>9} {:>9} {:>9} {:>9} {:>9}",
        "δ [m]", "κ(Ψ_u)", "A err", "B err", "|A−B|"
    );
    for r in &methods {
        println!(
            "{:9.2e} {:9.2e} {:9.1e} {:9.1e} {:9.1e}",
            r.delta, r.condition, r.error_a, r.error_b, r.a_minus_b
        );
    }
    write("stability_methods.svg", charts::methods_chart(&methods)?)?;
    for name in [
        "stability_limit",
        "stability_branch",
        "stability_iterations",
        "stability_methods",
    ] {
        println!("wrote {}", figures.join(format!("{name}.svg")).display());
    }
    Ok(())
}
