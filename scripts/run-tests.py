#!/usr/bin/env python3
"""Run every test binary of the workspace, two at a time (scripts/test).

`cargo test` runs its test binaries one after another, and most of the
long ones spend their time in one simulation on one core; on two cores
half the machine idles. This builds every test binary once (`cargo test
--workspace --no-run`), then runs them in two lanes, longest first (the
times of the last run, in target/test-times.json, else those of a full run
committed in scripts/test-times.json), each in its package's
folder and with `.cargo/config.toml`'s [env] as cargo runs it, then the doc
tests. Each binary's output is
printed whole when it ends. Closes with one line over all binaries,
`tests: N passed, M failed`, and exits 1 when any binary failed.

    scripts/run-tests.py [--lanes N] [-- ARGS passed to every test binary]
"""

import json
import os
import subprocess
import sys
import tomllib
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TIMES = ROOT / "target" / "test-times.json"
# The times of a full run, committed: the order on a fresh clone.
COMMITTED_TIMES = ROOT / "scripts" / "test-times.json"


def binaries():
    """Every test binary: (name, executable, package folder)."""
    out = subprocess.run(
        ["cargo", "test", "--workspace", "--no-run", "--message-format=json-render-diagnostics"],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        check=True,
        text=True,
    ).stdout
    found = []
    for line in out.splitlines():
        try:
            m = json.loads(line)
        except json.JSONDecodeError:
            continue
        if m.get("reason") != "compiler-artifact" or not m.get("executable"):
            continue
        if not m.get("profile", {}).get("test"):
            continue
        target = m["target"]
        kind = target["kind"][0]
        package = m["package_id"].split("#")[0].rsplit("/", 1)[-1]
        name = f"{package}::{target['name']}" if kind == "test" else f"{package} ({kind})"
        folder = Path(m["manifest_path"]).parent
        found.append((name, m["executable"], folder))
    return found


def cargo_env():
    """The environment cargo gives a test: ours, with `.cargo/config.toml`'s
    [env] table (RUST_MIN_STACK: rust-hdl's signals are large)."""
    env = dict(os.environ)
    try:
        table = tomllib.loads((ROOT / ".cargo" / "config.toml").read_text()).get("env", {})
    except OSError:
        table = {}
    for key, value in table.items():
        value = value["value"] if isinstance(value, dict) else value
        env.setdefault(key, str(value))
    return env


def main():
    args = sys.argv[1:]
    lanes = 2
    if args[:1] == ["--lanes"]:
        lanes, args = int(args[1]), args[2:]
    extra = args[1:] if args[:1] == ["--"] else args
    todo = binaries()
    last = {}
    for times in (TIMES, COMMITTED_TIMES):
        try:
            last = json.loads(times.read_text())
            break
        except (OSError, ValueError):
            continue
    # Longest first: a long binary started last would run alone at the end.
    todo.sort(key=lambda b: -last.get(b[0], 0.0))
    env = cargo_env()
    lock = threading.Lock()
    results = {}
    started = time.time()

    def lane():
        while True:
            with lock:
                if not todo:
                    return
                name, exe, folder = todo.pop(0)
            t = time.time()
            run = subprocess.run(
                [exe, *extra],
                cwd=folder,
                env=env,
                stdout=subprocess.PIPE,
                stderr=subprocess.STDOUT,
                text=True,
            )
            seconds = time.time() - t
            with lock:
                results[name] = (run.returncode, seconds, run.stdout)
                print(f"     Running {name} ({seconds:.1f} s)", flush=True)
                sys.stdout.write(run.stdout)
                sys.stdout.flush()

    threads = [threading.Thread(target=lane) for _ in range(lanes)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    # Doc tests: cargo runs them itself.
    t = time.time()
    doc = subprocess.run(
        ["cargo", "test", "--workspace", "--doc"],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )
    results["doc tests"] = (doc.returncode, time.time() - t, doc.stdout)
    print(f"     Running doc tests ({results['doc tests'][1]:.1f} s)")
    sys.stdout.write(doc.stdout)
    TIMES.parent.mkdir(parents=True, exist_ok=True)
    TIMES.write_text(json.dumps({k: round(v[1], 1) for k, v in results.items()}, indent=1))
    passed = failed = 0
    for _, _, text in results.values():
        for line in text.splitlines():
            if line.startswith("test result:"):
                words = line.split()
                passed += int(words[3])
                failed += int(words[5])
    bad = sorted(k for k, v in results.items() if v[0] != 0)
    print(f"test binaries: {len(results)} in {time.time() - started:.0f} s, {lanes} at a time")
    if bad:
        print("failed: " + ", ".join(bad))
    print(f"tests: {passed} passed, {failed} failed")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
