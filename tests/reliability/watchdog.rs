//! The watchdog every campaign runs its cases under: each on a thread of
//! its own (the default 2 MiB stack of a spawned thread, not the main
//! thread's 8), a panic caught, and a case that outlives the time limit
//! counted as hung.

use std::sync::mpsc;
use std::time::Duration;

/// The longest a case may take (`LINKAGE_TIME_LIMIT` seconds, default 120):
/// far beyond any legitimate one, even unoptimised, so that running out
/// means a hang.
pub(crate) fn time_limit() -> Duration {
    let seconds = std::env::var("LINKAGE_TIME_LIMIT")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(120);
    Duration::from_secs(seconds)
}

/// How a case ended.
pub(crate) enum Ended<T> {
    Done(T),
    Panicked(String),
    Hung,
}

/// Runs `f` on a thread of its own and waits at most [`time_limit`].
pub(crate) fn watched<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> Ended<T> {
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
        let _ = send.send(outcome);
    });
    match receive.recv_timeout(time_limit()) {
        Ok(Ok(value)) => Ended::Done(value),
        Ok(Err(payload)) => Ended::Panicked(
            payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_default(),
        ),
        Err(_) => Ended::Hung,
    }
}
