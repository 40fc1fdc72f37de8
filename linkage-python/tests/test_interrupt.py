"""Ctrl-C interrupts a long call at once: the call raises
`KeyboardInterrupt` while its work is still running, instead of after it."""

import _thread
import threading
import time

import pytest

import linkage
from conftest import ROOT


def test_ctrl_c_interrupts_a_long_sweep():
    bar = linkage.Mechanism.from_file(ROOT / "mechanisms/four_bar.toml")
    started = time.perf_counter()
    whole = bar.sweep(steps=1_000_000)
    uninterrupted = time.perf_counter() - started
    assert len(whole) == 1_000_001
    timer = threading.Timer(uninterrupted / 10, _thread.interrupt_main)
    started = time.perf_counter()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        bar.sweep(steps=1_000_000)
    interrupted = time.perf_counter() - started
    timer.join()
    # Raised within a few looks for signals (50 ms each) of the signal,
    # not when the sweep would have ended.
    assert interrupted < uninterrupted / 2, (interrupted, uninterrupted)
