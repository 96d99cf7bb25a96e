"""Bulk keying against merely reading (issue 31): `exact-bezier key` and
`exact-bezier dedup` on N random bicubic patches as JSON Lines (written
by benches/make_dedup_input.py: N/2 patches and a moved copy of each),
against Python's `json.loads` of the same lines (parsing only, numbers as
floats), interleaved over several rounds; medians of wall-clock time.

Run through `benches/peers/run`, or alone from the repository root:

    python3 benches/peers/peer_bulk.py --cli target/release/exact-bezier [--patches 100000] [--rounds 3]

Ours runs on all cores (the machine's; `nproc` is printed), `json.loads`
on one. The last line printed is the JSON object of ratios ours/peer.
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time


def make_input(patches, path):
    here = os.path.dirname(os.path.abspath(__file__))
    maker = os.path.join(here, "..", "make_dedup_input.py")
    with open(path, "w") as out:
        subprocess.run([sys.executable, maker, "--jsonl", str(patches // 2)], stdout=out, check=True)


def json_loads(path):
    start = time.perf_counter()
    with open(path) as f:
        for line in f:
            json.loads(line)
    return time.perf_counter() - start


def ours(cli, command, path):
    """Wall-clock seconds and the largest resident set (MB) of one run."""
    start = time.perf_counter()
    child = subprocess.Popen([cli, command, path], stdout=subprocess.DEVNULL)
    _, status, usage = os.wait4(child.pid, 0)
    seconds = time.perf_counter() - start
    if status != 0:
        sys.exit(f"{cli} {command} failed with status {status}")
    return seconds, usage.ru_maxrss / 1024


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", required=True, help="path of the release exact-bezier binary")
    ap.add_argument("--patches", type=int, default=100_000)
    ap.add_argument("--rounds", type=int, default=3)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "patches.jsonl")
        make_input(args.patches, path)
        runs = {"json_loads": [], "key": [], "dedup": []}
        rss = 0
        for r in range(args.rounds):
            runs["json_loads"].append(json_loads(path))
            for command in ("key", "dedup"):
                seconds, mb = ours(args.cli, command, path)
                runs[command].append(seconds)
                rss = max(rss, mb)
            print(f"round {r + 1}/{args.rounds} done", flush=True)
    med = {k: statistics.median(v) for k, v in runs.items()}
    print(f"\n{args.patches} bicubic patches (JSON Lines), {os.cpu_count()} cores, "
          f"largest resident set of ours {rss:.0f} MB")
    print("| work | seconds | ours / json.loads |")
    print("| --- | --- | --- |")
    for k in ("json_loads", "key", "dedup"):
        print(f"| {k} | {med[k]:.3f} | {med[k] / med['json_loads']:.3g} |")
    print()
    print(json.dumps({
        "key_vs_json_loads": round(med["key"] / med["json_loads"], 4),
        "dedup_vs_json_loads": round(med["dedup"] / med["json_loads"], 4),
    }))


if __name__ == "__main__":
    main()
