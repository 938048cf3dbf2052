#!/usr/bin/python3
# Strong-scaling benchmark of ewaview-mpi: one volume drawn on P = 1, 2, 4, 8 ranks, N times each,
# the medians of each rank count's render, composite, bytes and memory figures in one table.
"""Runs `mpirun -np P ewaview-mpi VOLUME --output ... --stats --termination 1` for each P,
repeats N rounds (each round runs every P once, so a machine that slows down hits every P alike)
and prints, for each P, the median over the rounds of: the ranks' render times (least, median,
greatest rank), the composite time, the bytes each rank sent in the composite (`bytes_sent` in
--stats' bricks; "n/a" where --stats has none), the ranks' peak resident memory, the most voxels a
rank read, and the wall time and CPU time (all ranks, user and system) of the whole mpirun. --csv writes the same rows as CSV.

The memory run (a volume larger than one rank's address-space limit, 8 ranks under prlimit) is
scripts/mpi_scale.sh; this program measures time against rank count on a volume every rank could
hold.
"""
import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

COLUMNS = [
    "ranks", "rounds", "render_ms_min", "render_ms_median", "render_ms_max", "composite_ms",
    "bytes_sent_min", "bytes_sent_median", "bytes_sent_max", "picture_bytes", "peak_rss_mib_min",
    "peak_rss_mib_median", "peak_rss_mib_max", "voxels_read_max", "ghost", "wall_s", "cpu_s"
]


def parse_args(argv):
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    p = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        epilog="Arguments after -- go to ewaview-mpi unchanged (e.g. -- --classification pre).")
    p.add_argument("volume", nargs="?",
                   default=os.path.join(root, "..", "shared", "data", "engine", "engine.nhdr"),
                   help="the volume file (default: ../shared/data/engine/engine.nhdr)")
    p.add_argument("--synthetic", metavar="SPEC",
                   help="draw ewaview's --synthetic SPEC instead of a file (marschner-lobb:N is "
                   "read by bricks; other synthetic volumes are made whole on every rank)")
    p.add_argument("--ranks", default="1,2,4,8", help="rank counts, comma-separated (1,2,4,8)")
    p.add_argument("--repeats", type=int, default=3, help="rounds; the medians are reported (3)")
    p.add_argument("--resolution", default="512,512", help="picture size W,H (512,512)")
    p.add_argument("--binary", default=os.path.join(root, "build", "ewaview-mpi"),
                   help="ewaview-mpi (build/ewaview-mpi)")
    p.add_argument("--mpirun", default="mpirun", help="the MPI launcher (mpirun)")
    p.add_argument("--mpirun-args", default="--allow-run-as-root --oversubscribe",
                   help="launcher options before -np (default: --allow-run-as-root "
                   "--oversubscribe, for root and more ranks than cores)")
    p.add_argument("--csv", metavar="FILE", help="also write the table as CSV")
    p.add_argument("--raw", metavar="FILE",
                   help="also write every run's --stats line, one JSON object a line, with its "
                   "rank count, round and wall time")
    p.add_argument("--out", metavar="DIR", help="where the pictures go (a temporary folder)")
    # What follows "--" is ewaview-mpi's (argparse's REMAINDER would also take the options
    # written after the volume).
    extra = argv[argv.index("--") + 1:] if "--" in argv else []
    args = p.parse_args(argv[:argv.index("--")] if "--" in argv else argv)
    args.extra = extra
    try:
        args.ranks = [int(r) for r in args.ranks.split(",")]
    except ValueError:
        p.error(f"--ranks {args.ranks}: expected whole numbers, comma-separated")
    if not args.ranks or min(args.ranks) < 1 or args.repeats < 1:
        p.error("--ranks and --repeats must be at least 1")
    return args


def run_once(args, ranks, out_dir):
    """One mpirun; returns (the --stats object, wall seconds, CPU seconds of every process it
    started). Exits with its stderr on failure."""
    source = ["--synthetic", args.synthetic] if args.synthetic else [args.volume]
    command = ([args.mpirun] + args.mpirun_args.split() + ["-np", str(ranks), args.binary] +
               source + ["--output", os.path.join(out_dir, f"scale_np{ranks}.png"),
                         "--resolution", args.resolution, "--termination", "1", "--stats"] +
               args.extra)
    # The ranks' CPU time (user and system, all threads): the work done, which stays comparable
    # where more ranks than cores share the machine and their wall times stretch.
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    done = subprocess.run(command, capture_output=True, text=True)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    lines = [line for line in done.stdout.splitlines() if line.startswith("{")]
    if done.returncode != 0 or not lines:
        sys.exit(f"mpi_scale_bench: {' '.join(command)} failed (status {done.returncode}):\n"
                 f"{done.stderr.strip()}")
    return json.loads(lines[-1]), wall, cpu


def summarize(ranks, runs):
    """The medians over rounds of each figure of one rank count; `runs`: (stats, wall, cpu)."""
    def median_of(f):
        values = [f(s, w) for s, w, _ in runs]
        return None if any(v is None for v in values) else statistics.median(values)

    def over_ranks(s, key, pick):
        values = [b.get(key) for b in s["bricks"]]
        return None if any(v is None for v in values) else pick(values)

    row = {"ranks": ranks, "rounds": len(runs)}
    for key, name in (("render_ms", "render_ms"), ("bytes_sent", "bytes_sent"),
                      ("peak_rss_mb", "peak_rss_mib")):
        for suffix, pick in (("min", min), ("median", statistics.median), ("max", max)):
            row[f"{name}_{suffix}"] = median_of(lambda s, w: over_ranks(s, key, pick))
    row["composite_ms"] = median_of(lambda s, w: s["composite_ms"])
    row["picture_bytes"] = runs[0][0]["picture_bytes"]
    row["voxels_read_max"] = median_of(lambda s, w: over_ranks(s, "voxels_read", max))
    row["ghost"] = "x".join(str(g) for g in runs[0][0]["ghost"])
    row["wall_s"] = median_of(lambda s, w: w)
    row["cpu_s"] = statistics.median(c for _, _, c in runs)
    return row


def text(value, digits=1):
    if value is None:
        return "n/a"
    if isinstance(value, float) and not value.is_integer():
        return f"{value:.{digits}f}"
    return str(int(value)) if isinstance(value, (int, float)) else str(value)


def print_table(rows):
    print(f"{'P':>3} {'render ms min/med/max':>24} {'composite ms':>12} "
          f"{'bytes sent min/med/max':>26} {'peak MiB min/med/max':>22} {'voxels/rank':>12} "
          f"{'wall s':>7} {'CPU s':>6}")
    for r in rows:
        render = "/".join(text(r[f"render_ms_{s}"], 0) for s in ("min", "median", "max"))
        sent = ("n/a" if r["bytes_sent_max"] is None else
                "/".join(text(r[f"bytes_sent_{s}"], 0) for s in ("min", "median", "max")))
        rss = "/".join(text(r[f"peak_rss_mib_{s}"], 0) for s in ("min", "median", "max"))
        print(f"{r['ranks']:>3} {render:>24} {text(r['composite_ms']):>12} {sent:>26} {rss:>22} "
              f"{text(r['voxels_read_max'], 0):>12} {text(r['wall_s'], 2):>7} "
              f"{text(r['cpu_s'], 2):>6}")


def main(argv):
    args = parse_args(argv)
    out_dir = args.out or tempfile.mkdtemp(prefix="ewa_mpi_scale_bench_")
    os.makedirs(out_dir, exist_ok=True)
    raw = open(args.raw, "w") if args.raw else None
    runs = {p: [] for p in args.ranks}
    for round_index in range(args.repeats):
        for p in args.ranks:
            stats, wall, cpu = run_once(args, p, out_dir)
            runs[p].append((stats, wall, cpu))
            print(f"mpi_scale_bench: round {round_index + 1}/{args.repeats}, {p} ranks: "
                  f"{wall:.2f} s", file=sys.stderr)
            if raw:
                raw.write(json.dumps({"ranks": p, "round": round_index + 1, "wall_s": wall,
                                      "cpu_s": cpu, "stats": stats}) + "\n")
    if raw:
        raw.close()
    rows = [summarize(p, runs[p]) for p in args.ranks]
    print_table(rows)
    if args.csv:
        with open(args.csv, "w") as f:
            f.write(",".join(COLUMNS) + "\n")
            for r in rows:
                f.write(",".join("n/a" if r[c] is None else
                                 (f"{r[c]:.3f}".rstrip("0").rstrip(".")
                                  if isinstance(r[c], float) else str(r[c])) for c in COLUMNS)
                        + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
