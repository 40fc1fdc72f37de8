//! Long calls that Ctrl-C interrupts: the work runs on a thread of its
//! own while the calling thread, the GIL released, waits for it and looks
//! for Python's signals between waits. Interrupted, the call raises
//! `KeyboardInterrupt` at once and raises the work's flag, which a work
//! that can stop early (a synthesis, between starts) reads; the work's
//! result, when it comes, is dropped.

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, mpsc};
use std::time::Duration;

/// How often a waiting call looks for signals.
const LOOK: Duration = Duration::from_millis(50);

/// `work(stop)`, run off the calling thread; a signal's exception (Ctrl-C's
/// `KeyboardInterrupt`) raised as soon as it comes, and `stop` raised.
pub fn interruptible<T: Send + 'static>(
    py: Python<'_>,
    work: impl FnOnce(Arc<AtomicBool>) -> T + Send + 'static,
) -> PyResult<T> {
    let stop = Arc::new(AtomicBool::new(false));
    let flag = Arc::clone(&stop);
    let (sender, receiver) = mpsc::channel();
    std::thread::Builder::new()
        .name("linkage".into())
        .spawn(move || {
            // The receiver is gone if the call was interrupted.
            let _ = sender.send(work(flag));
        })
        .map_err(|e| PyRuntimeError::new_err(format!("cannot start the work's thread: {e}")))?;
    let mut receiver = receiver;
    loop {
        let (back, received) = py.detach(move || {
            let received = receiver.recv_timeout(LOOK);
            (receiver, received)
        });
        receiver = back;
        match received {
            Ok(result) => return Ok(result),
            Err(mpsc::RecvTimeoutError::Timeout) => {
                if let Err(signal) = py.check_signals() {
                    stop.store(true, Ordering::Relaxed);
                    return Err(signal);
                }
            }
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                return Err(PyRuntimeError::new_err(
                    "the work's thread stopped without a result (a bug in linkage: please report it)",
                ));
            }
        }
    }
}
