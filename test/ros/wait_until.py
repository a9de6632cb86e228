"""Waiting on a condition with a deadline, for the Python rostests (test/core/wait_until.h in C++)."""

import time


def wait_until(condition, timeout, step=0.02):
    """Polls condition every step s until it holds or timeout s pass; returns its last value."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if condition():
            return True
        time.sleep(step)
    return condition()
