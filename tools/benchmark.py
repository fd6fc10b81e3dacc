#!/usr/bin/python3
"""snell's speed against Embree and POV-Ray 3.7, measured in one run on this machine; writes a markdown table.

Usage (from the project root, after configuring with -DSNELL_BUILD_BENCH=ON and building):
  tools/benchmark.py [--bin build/snell] [--bench build/bench/snell_bench] [--runs N] [--quick]
                     [--scenes NAME,NAME] [--benchmark-size WxH] [--out docs/benchmark.md]

1. Ray throughput of each accelerator (Google Benchmark, build/bench/snell_bench) against the Embree back end
   on the same 10,000 spheres and rays: coherent primary rays and incoherent random rays.
2. Wall time of snell and of POV-Ray 3.7 (`povray`, the same flags, +A0.3 +WT2) on the conformance scenes
   (../shared/conformance/scenes.tsv, 320x240) and on POV-Ray's advanced/benchmark/benchmark.pov (640x480;
   160x120 with --quick), with the SSIM of snell's image to POV-Ray's; a scene snell cannot parse or render
   is listed as such and skipped.
3. Peak memory (maximum resident set) of each, from the kernel's accounting of the child process (wait4).
Every figure is the median of --runs runs (default 3; --quick: 1 run of benchmark.pov and 6 scenes).
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = Path("/usr/share/doc/povray/examples")
INCLUDE = "/usr/share/povray-3.7/include"
CONFORMANCE = ROOT.parent / "shared" / "conformance"
IMGDIFF = ROOT.parent / "shared" / "tools" / "imgdiff"
QUICK_SCENES = ["primitiv", "blob", "csg_granite", "pigment", "spotlite", "chess2"]
TIMEOUT_S = 900


def run_child(cmd, cwd):
    """Runs `cmd`; returns (exit code, wall seconds, peak resident set in MiB)."""
    start = time.monotonic()
    with open(os.devnull, "wb") as null:
        child = subprocess.Popen(cmd, cwd=cwd, stdout=null, stderr=null)
        try:
            _, status, usage = os.wait4(child.pid, 0)
        except KeyboardInterrupt:
            child.kill()
            raise
    child.returncode = os.waitstatus_to_exitcode(status)
    return child.returncode, time.monotonic() - start, usage.ru_maxrss / 1024


def ssim(a, b):
    out = subprocess.run(["/usr/bin/python3", str(IMGDIFF), str(a), str(b), "--json"], capture_output=True,
                         text=True, check=False)
    try:
        return json.loads(out.stdout)["ssim"]
    except (ValueError, KeyError):
        return None


# The repetitions of all benchmarks run in random order, so that a slow spell of the shared machine falls on
# Embree and the accelerator compared with it alike, not on the repetitions of one of them.
INTERLEAVED = ["--benchmark_enable_random_interleaving=true"]


def throughput(bench, runs):
    """Median rays/s per (accelerator, ray set) from snell_bench at 10,000 spheres."""
    if not Path(bench).is_file():
        print(f"benchmark: no {bench}; configure with -DSNELL_BUILD_BENCH=ON to measure ray throughput",
              file=sys.stderr)
        return None
    out = subprocess.run([bench, "--benchmark_filter=(embree|bvh|octree|grid)_(primary|random)/10000$",
                          f"--benchmark_repetitions={runs}", *INTERLEAVED, "--benchmark_format=json"],
                         capture_output=True, text=True, check=True)
    samples = {}
    for b in json.loads(out.stdout)["benchmarks"]:
        if b.get("run_type") != "iteration":
            continue
        kind, rays = b["name"].split("/")[1].split("_")  # "run/bvh_random/10000"
        samples.setdefault((kind, rays), []).append(b["rays/s"])
    return {key: statistics.median(values) for key, values in samples.items()}


TRIANGLE_ROWS = [("raw_embree", "Embree alone (float)"), ("embree", "embree"), ("bvh", "bvh"),
                 ("octree", "octree"), ("grid", "grid"), ("embree_mesh", "embree, one mesh"),
                 ("bvh_mesh", "bvh, one mesh (its own tree)")]
TRIANGLE_SETS = ["primary", "random", "shadow"]


def triangle_throughput(bench, runs):
    """Median rays/s per (row, ray set) from snell_bench's 100k-triangle soup (bench/triangle_bench.cpp)."""
    if not Path(bench).is_file():
        return None
    out = subprocess.run([bench, "--benchmark_filter=^triangles/", f"--benchmark_repetitions={runs}",
                          *INTERLEAVED, "--benchmark_format=json"], capture_output=True, text=True, check=True)
    samples, costs = {}, {}
    for b in json.loads(out.stdout)["benchmarks"]:
        if b.get("run_type") != "iteration":
            continue
        row, rays = b["name"].split("/")[1].rsplit("_", 1)  # "triangles/bvh_mesh_random"
        if "bvh/embree" in b:  # "triangles/bvh_against_embree_random": a ratio measured in turns
            samples.setdefault((row, rays), []).append(b["bvh/embree"])
            continue
        samples.setdefault((row, rays), []).append(b["rays/s"])
        if "nodes/ray" in b:  # the same every repetition: counted once per run, untimed
            costs[(row, rays)] = (b["nodes/ray"], b["tests/ray"])
    return {key: statistics.median(values) for key, values in samples.items()}, costs


TRIANGLE_COST_CAPTION = ("Node visits (leaves included) and primitives tested per query, counted in one untimed "
                         "pass (only the scene-level structures: the mesh rows' inner trees do not report to "
                         "the tally, and Embree's own nodes are not counted; its tests are the double-precision "
                         "ones after its float filter).")


def triangle_cost_table(costs):
    """Node visits and primitive tests per query for each scene-level structure and ray set, under
    TRIANGLE_COST_CAPTION."""
    lines = ["| structure | " + " | ".join(f"{s} nodes / tests per ray" for s in TRIANGLE_SETS) + " |",
             "|---|" + "---:|" * len(TRIANGLE_SETS)]
    for row, label in TRIANGLE_ROWS:
        if row == "raw_embree" or row.endswith("_mesh"):
            continue
        cells = [f"{costs[(row, s)][0]:.1f} / {costs[(row, s)][1]:.1f}" if (row, s) in costs else "–"
                 for s in TRIANGLE_SETS]
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    return lines


def triangle_table(rates):
    """The triangle throughput table, each set also as a fraction of Embree called directly."""
    lines = ["| structure | " + " | ".join(f"{s} rays/s | vs Embree" for s in TRIANGLE_SETS) + " |",
             "|---|" + "---:|---:|" * len(TRIANGLE_SETS)]
    for row, label in TRIANGLE_ROWS:
        cells = []
        for s in TRIANGLE_SETS:
            r, base = rates.get((row, s)), rates.get(("raw_embree", s))
            cells += ["–", "–"] if r is None or not base else [f"{r / 1e6:.3f} M", f"{r / base:.2f}x"]
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    # The own BVH and Embree timed in alternate passes in one benchmark (bench/triangle_bench.cpp,
    # bvh_against_embree): the ratio that the machine's drift between separate benchmarks does not move.
    turns = [rates.get(("bvh_against_embree", s)) for s in TRIANGLE_SETS]
    if any(t is not None for t in turns):
        cells = sum((["–", "–"] if t is None else ["", f"{t:.2f}x"] for t in turns), [])
        lines.append("| bvh, timed in turns with Embree alone | " + " | ".join(cells) + " |")
    return lines


def render_pair(name, scene_dir, scene_file, size, runs, snell, work):
    """Median wall time and peak memory of snell and povray on one scene, and the SSIM of their images."""
    w, h = size
    common = [f"+W{w}", f"+H{h}", "+A0.3", f"+L{INCLUDE}", "-D", "+WT2"]
    snell_png, pov_png = work / f"{name}-snell.png", work / f"{name}-pov.png"
    rows = {"snell": [], "povray": []}
    for _ in range(runs):
        code, wall, mem = run_child([snell, f"+I{scene_file}", f"+O{snell_png}", *common], scene_dir)
        if code != 0 or not snell_png.is_file():
            return {"name": name, "error": f"snell exit {code}"}
        rows["snell"].append((wall, mem))
        code, wall, mem = run_child(["povray", f"+I{scene_file}", f"+O{pov_png}", *common], scene_dir)
        if code != 0:
            return {"name": name, "error": f"povray exit {code}"}
        rows["povray"].append((wall, mem))
    med = {k: (statistics.median(t for t, _ in v), statistics.median(m for _, m in v)) for k, v in rows.items()}
    return {"name": name, "snell_s": med["snell"][0], "snell_mib": med["snell"][1], "pov_s": med["povray"][0],
            "pov_mib": med["povray"][1], "ssim": ssim(snell_png, pov_png)}


def scene_table(results, summary=True):
    lines = ["| scene | snell s | POV-Ray s | speed-up | SSIM | snell MiB | POV-Ray MiB |",
             "|---|---:|---:|---:|---:|---:|---:|"]
    for r in results:
        if "error" in r:
            lines.append(f"| {r['name']} | – | – | – | – | – | – ({r['error']}) |")
            continue
        s = "–" if r["ssim"] is None else f"{r['ssim']:.3f}"
        lines.append(f"| {r['name']} | {r['snell_s']:.2f} | {r['pov_s']:.2f} | {r['pov_s'] / r['snell_s']:.2f}x | "
                     f"{s} | {r['snell_mib']:.0f} | {r['pov_mib']:.0f} |")
    good = [r["pov_s"] / r["snell_s"] for r in results if "error" not in r and (r["ssim"] or 0) >= 0.95]
    if good and summary:
        lines.append("")
        lines.append(f"Median speed-up over the {len(good)} scenes rendered at SSIM >= 0.95: "
                     f"**{statistics.median(good):.2f}x** (POV-Ray time / snell time).")
    return lines


NOTES_HEADING = "## Notes on these runs"


def kept_notes(out):
    """The hand-written notes section of an earlier table (from its heading to the end), so that a new run
    replaces the tables and keeps what people wrote about earlier runs."""
    if not out.exists():
        return "\n"
    text = out.read_text()
    at = text.find("\n" + NOTES_HEADING)
    return "\n" if at < 0 else "\n" + text[at:].rstrip("\n") + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", default="build/snell")
    parser.add_argument("--bench", default="build/bench/snell_bench")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--scenes", default="", help="comma-separated conformance scene names")
    parser.add_argument("--out", default="docs/benchmark.md")
    parser.add_argument("--benchmark-size", default="",
                        help="WxH of benchmark.pov (default 640x480; 160x120 with --quick)")
    args = parser.parse_args()
    snell = str(Path(args.bin).resolve())
    if not os.access(snell, os.X_OK) or shutil.which("povray") is None:
        sys.exit("benchmark: needs the snell binary (--bin) and Debian's povray")

    work = Path(tempfile.mkdtemp(prefix="snell-benchmark-"))
    try:
        shutil.copytree(EXAMPLES, work / "examples")
        subprocess.run(["find", str(work / "examples"), "-name", "*.gz", "-exec", "gunzip", "-qf", "{}", "+"],
                       check=False)
        wanted = [s for s in args.scenes.split(",") if s] or (QUICK_SCENES if args.quick else None)
        scenes = []
        for line in (CONFORMANCE / "scenes.tsv").read_text().splitlines()[1:]:
            name, scene = line.split("\t")[:2]
            if wanted is None or name in wanted:
                scenes.append((name, scene))

        load = os.getloadavg()
        lines = ["# snell benchmark", "",
                 f"Measured by `tools/benchmark.py{' --quick' if args.quick else ''}"
                 f"{' --benchmark-size ' + args.benchmark_size if args.benchmark_size else ''}` on {time.strftime('%Y-%m-%d')}, "
                 f"{os.cpu_count()} cores, load average at start {load[0]:.1f}; medians of {args.runs} runs. "
                 "Other work shared the machine, so compare the ratios (measured side by side), not the times.", ""]

        rates = throughput(args.bench, args.runs)
        if rates:
            lines += ["## Ray throughput (10,000 spheres, 1 thread)", "",
                      "| accelerator | primary rays/s | vs Embree | incoherent rays/s | vs Embree |",
                      "|---|---:|---:|---:|---:|"]
            for kind in ["embree", "bvh", "octree", "grid"]:
                p, r = rates.get((kind, "primary")), rates.get((kind, "random"))
                if p is None or r is None:
                    continue
                lines.append(f"| {kind} | {p / 1e6:.2f} M | {p / rates[('embree', 'primary')]:.2f}x | "
                             f"{r / 1e6:.2f} M | {r / rates[('embree', 'random')]:.2f}x |")
            lines.append("")
            print("\n".join(lines[-7:]), flush=True)
        triangles, costs = triangle_throughput(args.bench, args.runs) or (None, None)
        if triangles:
            table = triangle_table(triangles) + ["", TRIANGLE_COST_CAPTION, ""] + triangle_cost_table(costs)
            lines += ["## Ray throughput (100,000 triangles, 1 thread)", "",
                      "A soup of small overlapping triangles (`bench/triangle_bench.cpp`): Embree called directly "
                      "on float triangles (rtcIntersect1 / rtcOccluded1) against each accelerator, which sees "
                      "them as scene objects and reports double-precision hits, and against one `mesh` "
                      "object; shadow rays are occlusion queries. \"vs Embree\" is the fraction of Embree "
                      "alone. The last row times the own BVH and Embree alone in alternate whole passes over "
                      "the same rays inside one benchmark, so the machine's drift between separate "
                      "benchmarks does not move its ratio.", ""] + table + [""]
            print("\n".join(table), flush=True)

        results = []
        for name, scene in scenes:
            path = work / "examples" / scene
            results.append(render_pair(name, path.parent, path.name, (320, 240), args.runs, snell, work))
            print(results[-1], flush=True)
        lines += ["## POV-Ray's example scenes (320x240, +A0.3 +WT2)", ""] + scene_table(results) + [""]

        bench_dir = work / "examples" / "advanced" / "benchmark"
        size = (160, 120) if args.quick else (640, 480)
        if args.benchmark_size:
            size = tuple(int(v) for v in args.benchmark_size.lower().split("x"))
        bench = render_pair("benchmark.pov", bench_dir, "benchmark.pov", size, 1 if args.quick else args.runs,
                            snell, work)
        print(bench, flush=True)
        lines += [f"## advanced/benchmark/benchmark.pov ({size[0]}x{size[1]}, +A0.3 +WT2)", ""]
        lines += scene_table([bench], summary=False) + [""]
        Path(args.out).write_text("\n".join(lines) + kept_notes(Path(args.out)))
        print(f"benchmark: wrote {args.out}")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
