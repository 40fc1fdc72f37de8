//! What the macro costs its user's build: for the worksheet's four-bar, the
//! two-loop six-bar and chains of N coupled four-bar loops (N = 1 … 32),
//! the expansion time of the macro's own function in-process, the lines and
//! tokens of the emitted code, and the release compile time of a crate
//! containing that one mechanism.
//!
//! ```sh
//! cargo run --release -p linkage-macros --example expansion_cost
//! ```
//!
//! writes `expansion_cost.csv` and `.svg` to `out/expansion_cost/` and
//! prints the table (`docs/refresh.sh` refreshes the committed ones). `--no-compile` skips the (slow) compile-time column.
#![allow(dead_code)]

// The macro's item assembly: the engine's `generate`.
use linkage_symbolic::generate as expand;
// The mechanisms measured, shared with the tapes' cost.
#[path = "common/cases.rs"]
mod cases;

use cases::{Case, chain, fourbar, sixbar};
use linkage::draw::chart::look::{COLOURS, MARKERS};
use linkage::draw::chart::{Chart, Colour, Dash, Panel};
use proc_macro2::{TokenStream, TokenTree};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

fn count_tokens(tokens: TokenStream) -> usize {
    tokens
        .into_iter()
        .map(|t| match t {
            TokenTree::Group(g) => 1 + count_tokens(g.stream()),
            _ => 1,
        })
        .sum()
}

struct Row {
    name: String,
    n: Option<usize>,
    m: usize,
    expansion: Duration,
    lines: usize,
    tokens: usize,
    compile: Option<Duration>,
}

fn measure(case: &Case, compile: Option<&Path>) -> Row {
    let attr: TokenStream = case.attr.parse().expect("attribute text");
    let item: TokenStream = case.item.parse().expect("struct text");
    let mut times = Vec::new();
    let mut output = TokenStream::new();
    for _ in 0..7 {
        let start = Instant::now();
        output = expand::expand(attr.clone(), item.clone());
        times.push(start.elapsed());
    }
    times.sort();
    let text = output.to_string();
    assert!(
        !text.contains("compile_error"),
        "{}: the attribute has errors",
        case.name
    );
    let file: syn::File = syn::parse2(output.clone()).expect("the expansion parses");
    let pretty = prettyplease::unparse(&file);
    let m = case
        .attr
        .split("v =")
        .next()
        .unwrap_or("")
        .matches(',')
        .count();
    Row {
        name: case.name.clone(),
        n: case.n,
        m: if case.n.is_some() {
            2 * case.n.unwrap_or(0)
        } else {
            m
        },
        expansion: times[times.len() / 2],
        lines: pretty.lines().count(),
        tokens: count_tokens(output),
        compile: compile.map(|dir| compile_time(dir, case)),
    }
}

/// The release compile time of a crate holding this one mechanism (its
/// dependencies already built).
fn compile_time(dir: &Path, case: &Case) -> Duration {
    let src = dir.join("src/lib.rs");
    let code = format!(
        "#![allow(dead_code)]\n#[linkage::linkage({})]\n{}\n",
        case.attr, case.item
    );
    std::fs::write(&src, code).expect("write the probe crate");
    let start = Instant::now();
    let status = std::process::Command::new(env!("CARGO"))
        .args(["build", "--release", "--offline", "--quiet"])
        .current_dir(dir)
        .status()
        .expect("run cargo");
    let elapsed = start.elapsed();
    assert!(
        status.success(),
        "{}: the probe crate does not build",
        case.name
    );
    elapsed
}

/// A crate depending on `linkage`, with its dependencies built once.
fn probe_crate(workspace: &Path) -> PathBuf {
    let dir = workspace.join("target/expansion-cost/probe");
    std::fs::create_dir_all(dir.join("src")).expect("create the probe crate");
    std::fs::write(
        dir.join("Cargo.toml"),
        format!(
            "[package]\nname = \"probe\"\nversion = \"0.0.0\"\nedition = \"2024\"\npublish = false\n\n\
             [dependencies]\nlinkage = {{ path = {:?} }}\n\n[workspace]\n",
            workspace.display().to_string()
        ),
    )
    .expect("write the probe manifest");
    std::fs::write(dir.join("src/lib.rs"), "").expect("write the probe crate");
    let status = std::process::Command::new(env!("CARGO"))
        .args(["build", "--release", "--offline", "--quiet"])
        .current_dir(&dir)
        .status()
        .expect("run cargo");
    assert!(
        status.success(),
        "the probe crate's dependencies do not build"
    );
    dir
}

fn main() {
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the workspace")
        .to_path_buf();
    let with_compile = !std::env::args().any(|a| a == "--no-compile");
    let probe = with_compile.then(|| probe_crate(&workspace));
    let mut cases = vec![fourbar(), sixbar()];
    cases.extend([1, 2, 4, 8, 16, 32].map(chain));
    let rows: Vec<Row> = cases
        .iter()
        .map(|c| {
            let row = measure(c, probe.as_deref());
            eprintln!("measured {}", row.name);
            row
        })
        .collect();

    let mut table = String::from(
        "| mechanism | m | expansion (median of 7) | emitted lines | emitted tokens | tokens / m | release compile |\n\
         |---|---:|---:|---:|---:|---:|---:|\n",
    );
    let mut csv = String::from("mechanism,n,m,expansion_ms,lines,tokens,compile_s\n");
    for r in &rows {
        let compile = r
            .compile
            .map_or("—".to_owned(), |d| format!("{:.2} s", d.as_secs_f64()));
        writeln!(
            table,
            "| {} | {} | {:.2} ms | {} | {} | {:.0} | {} |",
            r.name,
            r.m,
            r.expansion.as_secs_f64() * 1e3,
            r.lines,
            r.tokens,
            r.tokens as f64 / r.m as f64,
            compile
        )
        .unwrap();
        writeln!(
            csv,
            "{},{},{},{:.4},{},{},{}",
            r.name,
            r.n.map_or(String::new(), |n| n.to_string()),
            r.m,
            r.expansion.as_secs_f64() * 1e3,
            r.lines,
            r.tokens,
            r.compile
                .map_or(String::new(), |d| format!("{:.3}", d.as_secs_f64()))
        )
        .unwrap();
    }
    println!("{table}");
    // `out/expansion_cost/` (ignored by git), or LINKAGE_OUT (docs/refresh.sh).
    let figures = std::env::var_os("LINKAGE_OUT")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| workspace.join("out/expansion_cost"));
    std::fs::create_dir_all(&figures).expect("create the output folder");
    std::fs::write(figures.join("expansion_cost.csv"), csv).expect("write the CSV");
    chart(&rows, &figures.join("expansion_cost.svg"));
    println!("wrote {}", figures.join("expansion_cost.svg").display());
}

/// A labelled curve.
type Series = (&'static str, Vec<(f64, f64)>);

/// Log–log chart of the chain's cost against N, each quantity relative to
/// N = 1, with the slopes of N and N² for reference.
fn chart(rows: &[Row], path: &Path) {
    let chain: Vec<&Row> = rows.iter().filter(|r| r.n.is_some()).collect();
    let base = chain[0];
    let n = |r: &Row| r.n.unwrap_or(1) as f64;
    let mut series: Vec<Series> = vec![
        (
            "expansion time",
            chain
                .iter()
                .map(|r| {
                    (
                        n(r),
                        r.expansion.as_secs_f64() / base.expansion.as_secs_f64(),
                    )
                })
                .collect(),
        ),
        (
            "emitted tokens",
            chain
                .iter()
                .map(|r| (n(r), r.tokens as f64 / base.tokens as f64))
                .collect(),
        ),
        (
            "emitted lines",
            chain
                .iter()
                .map(|r| (n(r), r.lines as f64 / base.lines as f64))
                .collect(),
        ),
    ];
    if chain.iter().all(|r| r.compile.is_some()) {
        let c0 = base.compile.map_or(1.0, |d| d.as_secs_f64());
        series.push((
            "release compile time",
            chain
                .iter()
                .map(|r| (n(r), r.compile.map_or(0.0, |d| d.as_secs_f64()) / c0))
                .collect(),
        ));
    }
    let mut panel = Panel::new("cost / cost at N = 1")
        .x_log()
        .y_log()
        .x_range(1.0, 40.0)
        .y_range(0.5, 2000.0);
    for (label, slope, dash) in [("∝ N", 1.0, Dash::Dotted), ("∝ N²", 2.0, Dash::LongDash)] {
        let reference = (0..=40)
            .map(|i| {
                let n = 1.0 + 39.0 * f64::from(i) / 40.0;
                (n, n.powf(slope))
            })
            .collect();
        panel = panel
            .line(label, reference)
            .colour(Colour::GREY)
            .dash(dash)
            .width(0.7);
    }
    for (k, (label, points)) in series.into_iter().enumerate() {
        panel = panel
            .line_and_points(label, points)
            .colour(COLOURS[k])
            .dash(Dash::Solid)
            .marker(MARKERS[k]);
    }
    let svg = Chart::new(
        "Cost of the macro for a chain of N four-bar loops (relative to N = 1)",
        "N (loops; m = 2N dependent coordinates)",
    )
    .size(760, 480)
    .panel(panel)
    .render()
    .expect("the chart's values are finite");
    std::fs::write(path, svg).expect("write the SVG");
}
