"""Bulk dedup on Dask (docs/distributed.md): `exact_bezier.key` is the map
step on worker processes, a group-by the reduce step, and the classes are
exactly those of one `exact-bezier dedup` run over the same records."""

import random
from fractions import Fraction

import pytest

import exact_bezier as eb
from exact_bezier._bridge import json_input, run_json

distributed = pytest.importorskip(
    "distributed", reason="dask[distributed] is not installed (pip install 'dask[distributed]')"
)
import dask.bag as db  # noqa: E402  (after the skip)


def records(n_bases=40, copies=4, seed=29):
    """Curves with known duplicates: each base, and copies of it reversed,
    Möbius-reparameterized or degree-elevated; shuffled."""
    rng = random.Random(seed)
    out = []
    for _ in range(n_bases):
        pts = [[rng.randint(-9, 9), rng.randint(-9, 9)] for _ in range(rng.randint(2, 4))]
        ws = [Fraction(rng.randint(1, 9), rng.randint(1, 9)) for _ in pts]
        c = eb.Curve(pts, ws)
        out.append(c)
        for k in range(copies - 1):
            choice = rng.randrange(3)
            if choice == 0:
                out.append(eb.Curve(pts[::-1], ws[::-1]))
            elif choice == 1:
                out.append(eb.reparameterize(c, Fraction(rng.randint(1, 9), 10)))
            else:
                out.append(eb.elevate(c, 1 + k % 2))
    rng.shuffle(out)
    return out


def key_partition(lines_with_path, offsets):
    """The map step on a worker: (key, global index) for each line of one
    shard (one partition per shard, lines in order)."""
    out = []
    for i, (line, path) in enumerate(lines_with_path):
        (patch,) = eb.read_json(line)
        out.append((eb.key(patch), offsets[path.rsplit("/", 1)[-1]] + i))
    return out


def test_dask_keys_on_workers_group_into_the_dedup_classes(tmp_path):
    patches = records()
    shards, offsets, start = 4, {}, 0
    per = -(-len(patches) // shards)
    for s in range(shards):
        name = f"shard-{s}.jsonl"
        chunk = patches[s * per:(s + 1) * per]
        (tmp_path / name).write_text("".join(p.to_json() + "\n" for p in chunk))
        offsets[name], start = start, start + len(chunk)

    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        bag = db.read_text(str(tmp_path / "shard-*.jsonl"), include_path=True, blocksize=None)
        keyed = bag.map_partitions(key_partition, offsets)
        groups = keyed.groupby(lambda r: r[0]).map(lambda kv: sorted(i for _, i in kv[1]))
        classes = sorted(groups.compute())
        workers = client.run(lambda: __import__("os").getpid())
    assert len(set(workers.values())) == 2

    reference = run_json(["dedup", "-"], json_input(patches))
    assert classes == sorted(c["members"] for c in reference)
    assert len(classes) == 40  # the bases are distinct
