"""Child processes timed for the benches beside this file (manifold_peer.py, resin_peer.py):
wall time, peak RSS and the stderr tail of one run, and the best of several."""

import os
import subprocess
import tempfile
import threading
import time
from pathlib import Path

SLOW = 30.0  # seconds: one run above this is not repeated
CHILD_TIMEOUT = 900.0
TIME = Path("/usr/bin/time")


def run_timed(cmd, stdout_path=None, timeout=CHILD_TIMEOUT, rss=False, cwd=None, env=None):
    """Run `cmd`; (wall seconds, peak RSS in MiB or None, exit status, stderr tail).

    The peak RSS (`rss=True`) comes from `/usr/bin/time -f %M`, which adds its own exec to the
    wall time; without it the RSS is None (os.wait4's ru_maxrss is not used: a child forked
    from this process starts with this process's high-water mark)."""
    out = open(stdout_path, "wb") if stdout_path else subprocess.DEVNULL
    err = tempfile.TemporaryFile()
    rss_file = None
    if rss and TIME.exists():
        fd, rss_file = tempfile.mkstemp(prefix="bench.rss.")
        os.close(fd)
        cmd = [str(TIME), "-f", "%M", "-o", rss_file] + list(cmd)
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=out, stderr=err, stdin=subprocess.DEVNULL, cwd=cwd, env=env)
    # A blocking wait, the timeout from a timer thread: `p.wait(timeout=...)` polls with
    # sleeps that double up to 50 ms, so every time it measured was rounded up to the next
    # of 0.031, 0.063, 0.113, 0.163, ... s.
    expired = threading.Event()

    def expire():
        expired.set()
        p.kill()

    timer = threading.Timer(timeout, expire)
    timer.start()
    p.wait()
    wall = time.perf_counter() - t0
    timer.cancel()
    code = -9 if expired.is_set() else p.returncode
    if stdout_path:
        out.close()
    err.seek(0)
    tail = err.read()[-4000:].decode("utf-8", "replace")
    err.close()
    peak = None
    if rss_file:
        try:
            peak = int(Path(rss_file).read_text().split()[-1]) / 1024.0
        except (ValueError, IndexError):
            pass
        os.unlink(rss_file)
    return wall, peak, code, tail


def best_of(fn, runs=3):
    """Best of `runs` calls of fn() -> (seconds, ...) or None; one call when the first is slow."""
    best = None
    for k in range(runs):
        r = fn()
        if r is None:
            return None
        if best is None or r[0] < best[0]:
            best = r
        if k == 0 and r[0] > SLOW:
            break
    return best
