//! How long `text::build` takes on the four-bar of the Maple worksheet
//! (points and all): the median of many builds, of a text without
//! mistakes and of one with a misspelt name. Run optimised:
//!
//!     cargo run --release -p linkage-symbolic --features text --example text_build_time

use linkage_symbolic::text::{self, Equations, Parameter};
use std::time::{Duration, Instant};

const FOUR_BAR: &str = "
    u = [theta3, theta4],
    v = [theta2],
    points = [
        B = (l2 * theta2.cos(), l2 * theta2.sin()),
        C = (B.x + l3 * theta3.cos(), B.y + l3 * theta3.sin()),
    ],
    closure = [
        l2 * theta2.cos() + l3 * theta3.cos() + l4 * theta4.cos() - l1,
        l2 * theta2.sin() + l3 * theta3.sin() + l4 * theta4.sin(),
    ]";

fn median(mut samples: Vec<Duration>) -> Duration {
    samples.sort();
    samples[samples.len() / 2]
}

fn main() {
    let parameters = ["l1", "l2", "l3", "l4"].map(Parameter::new);
    let runs = 2000;
    let time = |f: &dyn Fn()| {
        (0..runs)
            .map(|_| {
                let start = Instant::now();
                f();
                start.elapsed()
            })
            .collect::<Vec<_>>()
    };
    let build = time(&|| {
        let built = text::build("FourBar", Equations::new(FOUR_BAR), &parameters);
        assert!(built.is_ok());
    });
    let misspelt = FOUR_BAR.replace("B.y + l3 * theta3", "B.y + l3 * thta3");
    let mistaken = time(&|| {
        let built = text::build("FourBar", Equations::new(&misspelt), &parameters);
        assert!(built.is_err());
    });
    println!(
        "text::build of the four-bar, median of {runs}: {:.3} ms; with a misspelt name: {:.3} ms",
        median(build).as_secs_f64() * 1e3,
        median(mistaken).as_secs_f64() * 1e3,
    );
}
