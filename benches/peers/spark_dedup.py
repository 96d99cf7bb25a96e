#!/usr/bin/env python3
"""Bulk dedup on Spark (docs/distributed.md, issue 29): `exact_bezier.key`
in `mapPartitions` is the map step, `groupBy` the reduce step; the classes
are checked against one `exact-bezier dedup` run, and the key throughput
is printed. Outside CI (PySpark is large).

    python3 -m venv /tmp/eb-spark && . /tmp/eb-spark/bin/activate
    pip install ./python pyspark
    python3 benches/peers/spark_dedup.py [--records 200000] [--shards 8]

It starts a standalone master and one worker on 127.0.0.1 (`spark-class
org.apache.spark.deploy.master.Master` / `...worker.Worker`, with the Java
on the PATH), runs the job on it with --cores executor cores, and stops
both. Input: JSON Lines shards of rational space curves of degree
2–4 (bases and reversed, Möbius-reparameterized or elevated copies), made
by this script in a temporary directory.
"""

import argparse
import json
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

import exact_bezier as eb
from exact_bezier._bridge import run_json


def make_records(n, seed=29):
    """JSON texts of `n` curves, about a quarter of them distinct."""
    rng = random.Random(seed)
    out = []
    while len(out) < n:
        pts = [[rng.randint(-99, 99), rng.randint(-99, 99), rng.randint(-99, 99)]
               for _ in range(rng.randint(3, 5))]
        ws = [Fraction(rng.randint(1, 99), rng.randint(1, 99)) for _ in pts]
        c = eb.Curve(pts, ws)
        out += [c.to_json(), eb.Curve(pts[::-1], ws[::-1]).to_json(),
                eb.reparameterize(c, Fraction(rng.randint(1, 9), 10)).to_json(),
                eb.elevate(c, 1).to_json()]
    out = out[:n]
    rng.shuffle(out)
    return out


def key_partition(rows):
    """The map step (on the executors): (key, index) per (index, line)."""
    import exact_bezier

    for index, line in rows:
        (patch,) = exact_bezier.read_json(line)
        yield exact_bezier.key(patch), index


def start_cluster(spark_home, cores, log_dir):
    cls = os.path.join(spark_home, "bin", "spark-class")
    env = dict(os.environ, SPARK_LOCAL_IP="127.0.0.1")
    master = subprocess.Popen(
        [cls, "org.apache.spark.deploy.master.Master", "--host", "127.0.0.1", "--port", "7077",
         "--webui-port", "18080"],
        env=env, stdout=open(os.path.join(log_dir, "master.log"), "w"), stderr=subprocess.STDOUT)
    time.sleep(5)
    worker = subprocess.Popen(
        [cls, "org.apache.spark.deploy.worker.Worker", "spark://127.0.0.1:7077", "--host",
         "127.0.0.1", "--cores", str(cores), "--webui-port", "18081"],
        env=env, stdout=open(os.path.join(log_dir, "worker.log"), "w"), stderr=subprocess.STDOUT)
    time.sleep(5)
    return master, worker


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--records", type=int, default=200_000)
    ap.add_argument("--shards", type=int, default=8)
    ap.add_argument("--cores", type=int, default=2)
    a = ap.parse_args()

    import pyspark
    from pyspark.sql import SparkSession

    work = tempfile.mkdtemp(prefix="eb-spark-")
    lines = make_records(a.records)
    per = -(-len(lines) // a.shards)
    for s in range(a.shards):
        with open(os.path.join(work, f"shard-{s:03}.jsonl"), "w") as f:
            f.writelines(line + "\n" for line in lines[s * per:(s + 1) * per])

    # The executors run this interpreter, which has exact_bezier installed.
    os.environ["PYSPARK_PYTHON"] = sys.executable
    spark_home = os.path.dirname(pyspark.__file__)
    master, worker = start_cluster(spark_home, a.cores, work)
    try:
        spark = (SparkSession.builder.master("spark://127.0.0.1:7077")
                 .appName("exact-bezier dedup")
                 .config("spark.driver.host", "127.0.0.1")
                 .config("spark.executor.cores", str(a.cores))
                 .config("spark.pyspark.python", sys.executable)
                 .getOrCreate())
        sc = spark.sparkContext
        # wholeTextFiles keeps each shard whole and in order: global index =
        # shard offset + line number.
        offsets = {}
        for s in range(a.shards):
            offsets[f"shard-{s:03}.jsonl"] = s * per
        files = sc.wholeTextFiles(os.path.join(work, "shard-*.jsonl"), minPartitions=a.shards)
        rows = files.flatMap(lambda kv: [
            (offsets[kv[0].rsplit("/", 1)[-1]] + i, line)
            for i, line in enumerate(kv[1].splitlines())
        ])
        t0 = time.perf_counter()
        keyed = rows.mapPartitions(key_partition).cache()
        n = keyed.count()
        t_key = time.perf_counter() - t0
        classes = (keyed.groupBy(lambda r: r[0])
                   .map(lambda kv: sorted(i for _, i in kv[1])).collect())
        t_all = time.perf_counter() - t0
        spark.stop()
    finally:
        worker.terminate()
        master.terminate()
        worker.wait()
        master.wait()

    t1 = time.perf_counter()
    reference = run_json(["dedup", "-"], "\n".join(lines))
    t_ref = time.perf_counter() - t1
    assert n == len(lines)
    assert sorted(classes) == sorted(c["members"] for c in reference), "classes differ from dedup"
    print(json.dumps({
        "records": n,
        "classes": len(classes),
        "executor_cores": a.cores,
        "key_seconds": round(t_key, 2),
        "keys_per_second": round(n / t_key),
        "keys_per_second_per_core": round(n / t_key / a.cores),
        "key_and_group_seconds": round(t_all, 2),
        "dedup_in_process_seconds": round(t_ref, 2),
        "classes_equal_dedup": True,
    }, indent=2))
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
