# Runs one mesher as a whole process and measures it: wall time (Python's
# monotonic clock around a blocking wait for the process; Popen.wait with a
# timeout polls with sleeps of up to 50 ms, which rounded every run up to
# the next poll) and peak RSS (GNU time's %M: the max RSS of the mesher
# itself, which it waits for). A run that exceeds the
# timeout is killed with its whole process group and recorded as "timeout"
# (with the peak RSS it had reached, from /proc); its address space is
# capped (RLIMIT_AS), so a mesher that runs away in memory fails instead of
# taking the machine down.
# Repeats: the median of 3 runs when the first is under 10 s, else 1 run.
import json
import os
import resource
import signal
import subprocess
import threading
import time

REPEAT_BELOW_S = 10.0


def peak_rss_mb_of_child(pid):
    """VmHWM of the mesher still running under GNU time (pid), or None."""
    try:
        with open("/proc/%d/task/%d/children" % (pid, pid)) as f:
            child = f.read().split()[0]
        with open("/proc/%s/status" % child) as f:
            return next(int(line.split()[1]) / 1024 for line in f if line.startswith("VmHWM:"))
    except (OSError, IndexError, ValueError, StopIteration):
        return None


def run_once(argv, cwd, timeout, log_path, memory_gb):
    """One run: {status: ok|failed|timeout, wall_s, rss_mb, exit_code}."""
    limit = int(memory_gb * 2**30)
    time_file = os.path.join(cwd, "time.txt")
    with open(log_path, "w") as log:
        start = time.monotonic()
        proc = subprocess.Popen(["/usr/bin/time", "-f", "%M", "-o", time_file] + argv, cwd=cwd,
                                stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
                                start_new_session=True,
                                preexec_fn=lambda: resource.setrlimit(resource.RLIMIT_AS, (limit, limit)))
        # A timer kills the run's process group at the timeout (noting the
        # peak RSS it had reached first); the wait itself blocks.
        killed = {}

        def kill():
            killed["rss_mb"] = peak_rss_mb_of_child(proc.pid)
            try:
                os.killpg(proc.pid, signal.SIGKILL)
            except ProcessLookupError:  # it ended as the timer fired
                pass

        timer = threading.Timer(timeout, kill)
        timer.start()
        code = proc.wait()
        wall = time.monotonic() - start
        timer.cancel()
        if killed:
            return {"status": "timeout", "wall_s": timeout, "rss_mb": killed["rss_mb"], "exit_code": None}
    rss_kib = None
    if os.path.exists(time_file):
        with open(time_file) as f:
            last = f.read().strip().splitlines()[-1:]
        if last and last[0].isdigit():
            rss_kib = int(last[0])
    return {"status": "ok" if code == 0 else "failed", "wall_s": wall,
            "rss_mb": rss_kib / 1024 if rss_kib is not None else None, "exit_code": code}


def run_measured(argv, cwd, timeout, log_path, memory_gb):
    """The median-of-3 rule; returns the run with the median wall time."""
    first = run_once(argv, cwd, timeout, log_path, memory_gb)
    if first["status"] != "ok" or first["wall_s"] >= REPEAT_BELOW_S:
        return first
    runs = [first] + [run_once(argv, cwd, timeout, log_path, memory_gb) for _ in range(2)]
    if any(r["status"] != "ok" for r in runs):
        return next(r for r in runs if r["status"] != "ok")
    return sorted(runs, key=lambda r: r["wall_s"])[1]


def check_mesh(partet, mesh, surface, timeout):
    """partet check MESH --surface SURFACE --json: (result dict or None, error text)."""
    try:
        p = subprocess.run([partet, "check", mesh, "--surface", surface, "--json"], capture_output=True,
                           text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "check timed out"
    try:
        return json.loads(p.stdout), ""
    except ValueError:
        return None, (p.stderr.strip() or "check printed no JSON")[:300]
