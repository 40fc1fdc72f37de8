//! Tolerance analysis of the Maple worksheet's four-bar and of the shaping
//! machine of the Mathcad course project: the linear (worst-case, RSS, σ)
//! spreads from the exact sensitivities, beside a Monte Carlo run of
//! 100 000 designs drawn within the tolerances.
//!
//! 1. The worksheet's four-bar (80, 20, 50, 70 mm) under ISO 2768-f
//!    (±0.1 mm up to 30 mm, ±0.15 mm up to 120 mm), at 400 rpm: the
//!    rocker's angle, velocity and acceleration, the transmission angle,
//!    the band around the coupler curve of G3, the rocker's swing and the
//!    time ratio.
//! 2. The same four-bar with a coupler of 30.3 mm, 0.3 mm short of the
//!    Grashof limit: near θ2 = 180° coupler and rocker almost stretch out,
//!    the sensitivities grow without bound, and some designs of the band
//!    lock up. There the linear estimate fails, and the Monte Carlo run
//!    shows how.
//! 3. The shaper's stroke and quick-return ratio, by the envelope theorem
//!    at the located dead positions.
//!
//! Writes to `out/tolerance/`: `coupler_band.svg`, `importance.svg`,
//! `linear_vs_monte_carlo.svg`, and `bands.csv` (every output at every
//! step: nominal, linear worst case, RSS and σ, Monte Carlo mean, σ, min,
//! max).
//!
//!     cargo run --release --example tolerance

mod charts;
mod studies;

#[path = "../shaper/machine.rs"]
mod machine;
#[path = "../support/output.rs"]
mod output;

use std::fmt::Write as _;
use studies::{CycleStudy, Located};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let folder = output::folder("tolerance")?;
    let worksheet = studies::four_bar("the worksheet's four-bar", 50.0)?;
    let near_limit = studies::four_bar("coupler 30.3 mm: near the Grashof limit", 30.3)?;
    let shaper = studies::shaper()?;

    println!("{}", report(&worksheet));
    println!("{}", report(&near_limit));
    println!("{}", located(&shaper.name, &shaper.located));

    std::fs::write(folder.join("bands.csv"), csv(&[&worksheet, &near_limit]))?;
    std::fs::write(
        folder.join("coupler_band.svg"),
        charts::coupler_band(&worksheet)?,
    )?;
    std::fs::write(
        folder.join("importance.svg"),
        charts::importance(&worksheet, &shaper)?,
    )?;
    std::fs::write(
        folder.join("linear_vs_monte_carlo.svg"),
        charts::linear_vs_monte_carlo(&worksheet, &near_limit)?,
    )?;
    println!("written to {}", folder.display());
    Ok(())
}

/// The table of one four-bar: each output at the pose of its largest
/// linear spread, linear against Monte Carlo.
fn report(study: &CycleStudy) -> String {
    let mut t = String::new();
    let samples = study.samples.samples;
    let failed = study.samples.failures.len();
    let _ = writeln!(
        t,
        "## {}: linear estimate against {samples} Monte Carlo samples ({failed} do not run the whole cycle)\n",
        study.name
    );
    let _ = writeln!(
        t,
        "| output | unit | at θ2 | nominal | worst case ± | RSS ± | σ linear | σ Monte Carlo | Monte Carlo min … max − nominal | most from |"
    );
    let _ = writeln!(t, "|---|---|---:|---:|---:|---:|---:|---:|---:|---|");
    for (o, band) in study.cycle.bands.iter().enumerate() {
        let (unit, scale) = studies::unit(&band.name);
        let Some((k, spread)) = band.largest() else {
            let _ = writeln!(
                t,
                "| {} | {unit} | no pose has sensitivities | | | | | | | |",
                band.name
            );
            continue;
        };
        let mc = &study.samples.statistics[o][k];
        let nominal = band.value[k];
        let most = study.most_important(o);
        let _ = writeln!(
            t,
            "| {} | {unit} | {:.0}° | {:.4} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:+.3e} … {:+.3e} | {most} |",
            band.name,
            band.v[k][0].to_degrees(),
            nominal * scale,
            spread.worst_case * scale,
            spread.rss * scale,
            spread.sigma * scale,
            mc.std() * scale,
            (mc.min - nominal) * scale,
            (mc.max - nominal) * scale,
        );
    }
    t.push('\n');
    t.push_str(&located(&study.name, &study.located));
    t
}

/// The table of located quantities (the swing, the stroke, the time
/// ratio): linear against Monte Carlo.
fn located(name: &str, rows: &[Located]) -> String {
    let mut t = String::new();
    let _ = writeln!(t, "### {name}: located extremes\n");
    let _ = writeln!(
        t,
        "| quantity | nominal | worst case ± | RSS ± | σ linear | σ Monte Carlo | Monte Carlo mean − nominal | min … max − nominal | most from |"
    );
    let _ = writeln!(t, "|---|---:|---:|---:|---:|---:|---:|---:|---|");
    for row in rows {
        let s = &row.spread;
        let mc = &row.monte_carlo;
        let _ = writeln!(
            t,
            "| {} | {:.6} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:+.1e} | {:+.3e} … {:+.3e} | {} |",
            row.name,
            row.nominal,
            s.worst_case,
            s.rss,
            s.sigma,
            mc.std(),
            mc.mean - row.nominal,
            mc.min - row.nominal,
            mc.max - row.nominal,
            row.most_important,
        );
    }
    t
}

/// Every output at every step of both four-bars.
fn csv(studies: &[&CycleStudy]) -> String {
    let mut out = String::from(
        "study,output,theta2_deg,nominal,worst_case,rss,sigma_linear,mc_mean,mc_sigma,mc_min,mc_max,mc_count\n",
    );
    for study in studies {
        for (o, band) in study.cycle.bands.iter().enumerate() {
            for (k, v) in band.v.iter().enumerate() {
                let s = band.spread[k].unwrap_or_default();
                let mc = &study.samples.statistics[o][k];
                let _ = writeln!(
                    out,
                    "{},{},{:.1},{:.9e},{:.6e},{:.6e},{:.6e},{:.9e},{:.6e},{:.9e},{:.9e},{}",
                    study.name,
                    band.name,
                    v[0].to_degrees(),
                    band.value[k],
                    s.worst_case,
                    s.rss,
                    s.sigma,
                    mc.mean,
                    mc.std(),
                    mc.min,
                    mc.max,
                    mc.count
                );
            }
        }
    }
    out
}
