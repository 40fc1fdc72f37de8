//! The Rust side of the Python binding's overhead: a mechanism file read
//! at run time, swept through `steps` steps of its drive range by the
//! library's API (`Loaded::swept`, `Linkage::sweep` on the view at its
//! sizes), timed `rounds` times; prints each round's seconds, one a line.
//! `benches/peers/python_overhead.py` runs it A/B against the same sweep
//! called from Python.
//!
//!     cargo run --release --example sweep_timing -- mechanisms/four_bar.toml 10000 5

use linkage::file::Loaded;
use linkage::prelude::*;
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let path = args.next().ok_or("give a mechanism file")?;
    let steps: usize = args.next().ok_or("give the steps")?.parse()?;
    let rounds: usize = args.next().ok_or("give the rounds")?.parse()?;
    let loaded = Loaded::read(path.as_ref())?;
    let bar = loaded.mechanism().fixed::<2, 1>()?;
    for _ in 0..rounds {
        let start = Instant::now();
        let swept = loaded.swept(&bar, steps)?;
        let sweep = bar.sweep(&swept.start, &swept.drive, &swept.options)?;
        let seconds = start.elapsed().as_secs_f64();
        assert_eq!(sweep.poses.len(), steps + 1);
        println!("{seconds}");
    }
    Ok(())
}
