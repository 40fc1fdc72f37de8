//! `linkage`, the command-line tool: a mechanism file (TOML) checked,
//! analysed at a pose, swept through its drive range, searched for the
//! extremes of its quantities, differentiated by its dimensions, its
//! tolerances stacked, its dimensions synthesized, drawn, and promoted to
//! Rust — the library's own analyses on the mechanism read at run time.

mod cli;
mod commands;
mod failure;
mod load;
mod progress;
mod sizes;
mod table;

use clap::Parser;
use cli::{Cli, Command};
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match &cli.command {
        Command::Check(input) => commands::check::run(input),
        Command::Equations(input) => commands::equations::run(input),
        Command::Dxf(args) => commands::dxf::run(args),
        Command::Serve(args) => commands::serve::run(args),
        Command::Import(args) => commands::import::run(args),
        Command::Export(args) => commands::export::run(args),
        Command::Analyze(args) => commands::analyze::run(args),
        Command::Sweep(args) => commands::sweep::run(args),
        Command::Extremes(args) => commands::extremes::run(args),
        Command::Sensitivities(args) => commands::sensitivities::run(args),
        Command::Tolerance(args) => commands::tolerance::run(args),
        Command::Synthesize(args) => commands::synthesize::run(args),
        Command::Draw(args) => commands::draw::run(args),
        Command::Expand(input) => commands::expand::run(input),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(failure) => {
            if !matches!(
                failure,
                failure::Failure::Mistakes | failure::Failure::AnalysisAt
            ) {
                eprintln!("error: {failure}");
            }
            ExitCode::from(failure.code())
        }
    }
}
