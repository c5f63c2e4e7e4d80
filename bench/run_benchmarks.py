#!/usr/bin/env python3
"""ClothTrack benchmarks: accuracy on the paper's protocol beside the published figures, ablations,
and speed and memory, measured by running `clothtrack align` (the product itself).

usage: bench/run [--quick] [--out DIR] [--update] [--reuse] [--shared DIR]

  --quick    a smoke run (under 10 minutes on 2 cores): shorter sequences, fewer variants
  --out      working folder (default out/bench-full or out/bench-quick); every run's output stays there
  --update   write the tables into BENCHMARKS.md (between its bench/run markers) and the plots into
             bench/results/; the default for the full mode
  --reuse    keep runs whose metrics.json already exists (to resume an interrupted benchmark)
  --shared   the shared data folder (default ../shared/data); runs that need it are left out,
             with a message, when it is absent

Writes OUT/benchmarks.md, OUT/results.json and OUT/*.png.
"""
import argparse
import datetime
import json
import os
import platform
import shutil
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
APP = ROOT / "build" / "bin" / "clothtrack"
BEGIN = "<!-- bench/run: begin (generated, do not edit by hand) -->"
END = "<!-- bench/run: end -->"
PUBLISHED = [  # (method, data, mean error cm, % within 10 cm): the papers' own figures
    ("Shehu et al. 2016 (the method followed here)", "samba", 3.9, 96.83),
    ("Allain et al. 2014", "average of crane, march2, samba, squat1", 3.6, 96.22),
    ("Allain et al. 2015", "average of crane, march2, samba, squat1", 3.9, 94.68),
]


def log(message):
    print("[bench] " + message, file=sys.stderr, flush=True)


class Bench:
    def __init__(self, out, reuse):
        self.out = out
        self.reuse = reuse
        self.commands = []
        self.ran = 0  # runs made now (not reused)

    def app(self, *args):
        command = [str(APP)] + [str(a) for a in args]
        shown = [os.path.relpath(a, ROOT) if a.startswith("/") else a for a in command]
        self.commands.append(" ".join(shown))
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

    def synth(self, preset, frames, seed=7, voxel=None):
        name = "%s-%d-s%d%s" % (preset, frames, seed, "-v%g" % voxel if voxel else "")
        folder = self.out / "data" / name
        if not (folder / "markers.csv").exists():
            log("synth %s" % name)
            extra = ["--voxel", voxel] if voxel else []
            self.app("synth", "--preset", preset, "--frames", frames, "--seed", seed, "-o", folder, *extra)
        return folder

    def simulate(self, source, seed):
        folder = self.out / "data" / ("%s-capture-s%d" % (source.name, seed))
        if not (folder / "frames").exists() or not any((folder / "frames").iterdir()):
            log("simulate-capture %s seed %d" % (source.name, seed))
            # Holes and noise make the seeds differ (without them the capture is deterministic).
            self.app("simulate-capture", source, "-o", folder, "--seed", seed, "--holes", 2, "--noise", 0.002)
        return folder

    def align(self, name, frames, truth=None, markers=None, work=None, extra=()):
        out = self.out / "runs" / name
        metrics_path = out / "metrics.json"
        if self.reuse and metrics_path.exists():
            log("align %s: reused" % name)
        else:
            log("align %s" % name)
            # A run of its own starts from nothing: the work folder of an earlier benchmark would
            # let the app reuse its landmarks and correspondences, and the stage times would read 0.
            # Runs given another run's work folder share it on purpose (that run made it just now).
            shutil.rmtree(out if work is None else out / "aligned", ignore_errors=True)
            args = ["align", frames, "-o", out, "--no-report"]
            if truth:
                args += ["--ground-truth", truth]
            if markers:
                args += ["--markers", markers]
            if work:
                args += ["--work", work]
            start = time.time()
            self.ran += 1
            self.app(*args, *extra)
            log("align %s: %.0f s" % (name, time.time() - start))
        metrics = json.loads(metrics_path.read_text())
        metrics["name"] = name
        return metrics


def machine():
    model = "unknown CPU"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    memory = 0
    try:
        for line in Path("/proc/meminfo").read_text().splitlines():
            if line.startswith("MemTotal"):
                memory = int(line.split()[1]) / 1024 / 1024
    except OSError:
        pass
    debian = Path("/etc/debian_version").read_text().strip() if Path("/etc/debian_version").exists() else "?"
    commit = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip() or "?"
    return {"cpu": model, "cores": os.cpu_count(), "memory_gb": round(memory, 1), "debian": debian,
            "kernel": platform.release(), "commit": commit,
            "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")}


def per_frame(m, stage):
    return m["stage_seconds"].get(stage, 0.0) / m["frames"]


def cm(value):
    return "%.2f" % (100 * value)


def pct(value):
    return "%.2f" % (100 * value)


def accuracy_table(rows):
    lines = ["| sequence | frames | template frame (vertices) | mean (cm) | median (cm) | p90 (cm) | < 5 cm (%) "
             "| < 10 cm (%) | worst frame (mean cm) | drift (mm/frame) | markers (cm) | s/frame |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for label, m in rows:
        marker = cm(m["marker_mean_error_m"]) if "marker_mean_error_m" in m else "-"
        lines.append("| %s | %d | %d (%d) | %s | %s | %s | %s | %s | %d (%s) | %.3f | %s | %.2f |" % (
            label, m["frames"], m["template_frame"], m["template_vertices"], cm(m["mean_vertex_error_m"]),
            cm(m["median_vertex_error_m"]), cm(m["p90_vertex_error_m"]), pct(m["within_5cm"]),
            pct(m["within_10cm"]), m["worst_frame"], cm(m["worst_frame_mean_error_m"]),
            1000 * m["drift_m_per_frame"], marker, m["seconds_per_frame"]))
    return lines


def stage_table(rows, first_column):
    lines = ["| %s | template vertices | read | body fit | select | correspond | fit | evaluate | total s/frame "
             "| peak MB |" % first_column, "|---|---|---|---|---|---|---|---|---|---|"]
    for label, m in rows:
        lines.append("| %s | %d | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | **%.2f** | %.0f |" % (
            label, m["template_vertices"], per_frame(m, "read"), per_frame(m, "body_fit"),
            per_frame(m, "select_template"), per_frame(m, "correspond"), per_frame(m, "fit"),
            per_frame(m, "evaluate"), m["seconds_per_frame"], m["peak_rss_mb"]))
    return lines


def plots(out, accuracy, per_frame_run, sizes, lengths):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    written = []
    if per_frame_run:
        label, m = per_frame_run
        fig, ax = plt.subplots(figsize=(7, 3.2), dpi=110)
        ax.plot(m["frame_numbers"], [100 * e for e in m["per_frame_mean_error_m"]], label="mean")
        ax.plot(m["frame_numbers"], [100 * e for e in m["per_frame_p90_error_m"]], label="90th percentile", alpha=0.7)
        ax.axvline(m["frame_numbers"][m["template_frame"]], color="grey", linestyle=":", label="template frame")
        ax.set_xlabel("frame")
        ax.set_ylabel("vertex error (cm)")
        ax.set_title(label, fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(out / "per_frame_error.png")
        plt.close(fig)
        written.append("per_frame_error.png")
    if accuracy:
        fig, ax = plt.subplots(figsize=(6, 3.6), dpi=110)
        for label, m in accuracy:
            curve = m["cumulative_error"]
            ax.plot([100 * t for t in curve["threshold_m"]], [100 * f for f in curve["fraction"]], label=label)
        ax.set_xlabel("error threshold (cm)")
        ax.set_ylabel("vertices within (%)")
        ax.set_ylim(0, 100)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(out / "cumulative_error.png")
        plt.close(fig)
        written.append("cumulative_error.png")
    if len(sizes) > 1 or len(lengths) > 1:
        fig, axes = plt.subplots(1, 2, figsize=(8, 3.2), dpi=110)
        if sizes:
            x = [m["template_vertices"] for _, m in sizes]
            axes[0].plot(x, [m["seconds_per_frame"] for _, m in sizes], "o-", label="whole pipeline")
            axes[0].plot(x, [per_frame(m, "fit") for _, m in sizes], "s--", label="template fit")
            axes[0].set_xlabel("template vertices")
            axes[0].set_ylabel("seconds per frame")
            axes[0].legend(fontsize=8)
            axes[0].grid(alpha=0.3)
        if lengths:
            x = [m["frames"] for _, m in lengths]
            axes[1].plot(x, [m["seconds_per_frame"] for _, m in lengths], "o-", label="seconds per frame")
            axes[1].set_xlabel("frames")
            axes[1].set_ylabel("seconds per frame")
            twin = axes[1].twinx()
            twin.plot(x, [m["peak_rss_mb"] for _, m in lengths], "s--", color="C3", label="peak memory")
            twin.set_ylabel("peak memory (MB)")
            axes[1].grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig(out / "scaling.png")
        plt.close(fig)
        written.append("scaling.png")
    return written


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--out")
    parser.add_argument("--update", action="store_true")
    parser.add_argument("--reuse", action="store_true")
    parser.add_argument("--shared", default=str(ROOT.parent / "shared" / "data"))
    args = parser.parse_args()
    if not APP.exists():
        sys.exit("bench/run: %s is not built (run scripts/test or bench/run through its wrapper)" % APP)
    mode = "quick" if args.quick else "full"
    update = args.update or not args.quick
    out = Path(args.out or ROOT / "out" / ("bench-" + mode)).resolve()
    out.mkdir(parents=True, exist_ok=True)
    bench = Bench(out, args.reuse)
    shared = Path(args.shared)
    samba = shared / "vlasic-samba"
    captures = shared / "captures"
    if not samba.is_dir():
        log("%s not found: the samba rows are left out" % samba)
    started = time.time()

    accuracy, ablations, real, sizes, lengths, threads = [], [], [], [], [], []
    criteria = []  # (sequence, rest-pose run, area-ratio run): the template criterion compared
    area_ratio = ["--template-criterion", "area-ratio"]
    per_frame_run = None
    if samba.is_dir():
        frames_option = ["--frames", "0:30"] if args.quick else []
        label = "samba, frames 0-29 (paper protocol)" if args.quick else "samba (paper protocol)"
        work = out / "work" / "samba"
        main_run = bench.align("samba", samba, truth=samba, work=work, extra=frames_option)
        accuracy.append((label, main_run))
        per_frame_run = (label, main_run)
        ablations.append(("ClothTrack default (exact solve, landmark start prediction)", main_run))
        variants = [("without Ec (no correspondence term)", "no-ec", ["--no-correspondence"]),
                    ("L-BFGS (the paper's solver)", "lbfgs", ["--solver", "lbfgs"]),
                    ("the paper's template criterion (area ratio) instead of the rest pose", "area-ratio",
                     area_ratio)]
        if not args.quick:
            variants += [
                ("nearest neighbour only (sequential non-rigid ICP, no landmarks)", "icp",
                 ["--no-correspondence", "--predict-radius", "0"]),
                ("the paper's start (previous fit, no prediction)", "paper-start", ["--predict-radius", "0"]),
            ]
        for label_v, name, extra in variants:
            ablations.append((label_v, bench.align("samba-" + name, samba, truth=samba, work=work,
                                                   extra=frames_option + extra)))
            if name == "area-ratio":
                criteria.append((label, main_run, ablations[-1][1]))
        if not args.quick:
            ablations.append(("fixed template frame 0 instead of the automatic choice",
                              bench.align("samba-template0", samba, truth=samba, extra=["--template", "0"])))
            for seed in (1, 2):
                capture = bench.simulate(samba, seed)
                label_c = "samba re-meshed by the capture simulator, seed %d" % seed
                work_c = out / "work" / ("samba-capture-s%d" % seed)
                accuracy.append((label_c, bench.align("samba-capture-s%d" % seed, capture / "frames", truth=samba,
                                                      work=work_c)))
                criteria.append((label_c, accuracy[-1][1],
                                 bench.align("samba-capture-s%d-area-ratio" % seed, capture / "frames",
                                             truth=samba, work=work_c, extra=area_ratio)))
    presets = [("skirt-turn", 12)] if args.quick else [
        ("dress-walk", 40), ("skirt-turn", 40), ("trousers-squat", 40), ("dress-samba", 40)]
    for preset, count in presets:
        data = bench.synth(preset, count)
        label_p, work_p = "synthetic %s, %d frames" % (preset, count), out / "work" / ("%s-%d" % (preset, count))
        accuracy.append((label_p, bench.align("%s-%d" % (preset, count), data / "frames",
                                              truth=data / "ground_truth", markers=data / "markers.csv",
                                              work=work_p)))
        criteria.append((label_p, accuracy[-1][1],
                         bench.align("%s-%d-area-ratio" % (preset, count), data / "frames",
                                     truth=data / "ground_truth", markers=data / "markers.csv", work=work_p,
                                     extra=area_ratio)))
    if captures.is_dir():
        for capture in sorted(p for p in captures.iterdir() if p.is_dir())[: 1 if args.quick else None]:
            real.append((capture.name, bench.align("capture-" + capture.name, capture)))
    else:
        log("%s not found: the real-capture rows are left out" % captures)

    # Speed: template size through the capture's voxel size, sequence length, threads.
    size_frames = 6 if args.quick else 10
    for voxel in ([0.03, 0.015] if args.quick else [0.03, 0.021, 0.015, 0.0105]):
        data = bench.synth("dress-walk", size_frames, voxel=voxel)
        sizes.append(("voxel %.1f mm" % (1000 * voxel),
                      bench.align("size-v%g" % voxel, data / "frames", truth=data / "ground_truth")))
    length_voxel = 0.021 if args.quick else None
    for count in ([6, 12] if args.quick else [10, 20, 40, 80]):
        data = bench.synth("dress-walk", count, voxel=length_voxel)
        name = "length-%d" % count
        lengths.append(("%d frames" % count, bench.align(name, data / "frames", truth=data / "ground_truth")))
    thread_frames = 12 if args.quick else 20
    data = bench.synth("dress-walk", thread_frames, voxel=length_voxel)
    two = next(m for label, m in lengths if m["frames"] == thread_frames)
    one = bench.align("threads-1-%d" % thread_frames, data / "frames", truth=data / "ground_truth",
                      extra=["--threads", "1"])
    threads = [("1", one), (str(two["threads"]), two)]
    elapsed = time.time() - started
    previous = out / "results.json"
    if bench.ran == 0 and previous.exists():  # tables redrawn from earlier runs: their duration
        elapsed = json.loads(previous.read_text()).get("seconds", elapsed)

    info = machine()
    images = plots(out, accuracy, per_frame_run, sizes, lengths)
    command = "bench/run" + (" --quick" if args.quick else "")
    md = [BEGIN, "", "## Measured by `%s`" % command, "",
          "Machine: %s, %d cores, %.0f GB RAM, Debian %s (kernel %s); commit %s, %s. The whole benchmark took "
          "%.0f minutes. Every figure below comes from the `metrics.json` of one `clothtrack align` run; the "
          "commands are listed at the end." % (info["cpu"], info["cores"], info["memory_gb"], info["debian"],
                                                info["kernel"], info["commit"], info["date"], elapsed / 60), ""]
    if accuracy:
        md += ["### Accuracy", "",
               "Vertex error: each template vertex tied at the template frame to the closest ground-truth "
               "surface point; pooled over every frame but the template frame. Markers: 14 body markers of "
               "the synthetic captures, each tied to its nearest template vertex (paper Figure 9).", ""]
        md += accuracy_table(accuracy) + [""]
    md += ["### Published figures (same protocol)", "", "| method | data | mean (cm) | < 10 cm (%) |", "|---|---|---|---|"]
    md += ["| %s | %s | %.1f | %.2f |" % row for row in PUBLISHED]
    for label, m in accuracy:
        if label.startswith("samba") and "re-meshed" not in label:
            if args.quick:  # a subset of the frames: not comparable with the published figures
                md.append("| ClothTrack (quick mode: %d frames only, not comparable) | %s | %s | %s |" % (
                    m["frames"], label, cm(m["mean_vertex_error_m"]), pct(m["within_10cm"])))
            else:
                md.append("| **ClothTrack** | %s | **%s** | **%s** |" % (label, cm(m["mean_vertex_error_m"]),
                                                                         pct(m["within_10cm"])))
    md.append("")
    if real:
        md += ["### Real captures (no ground truth)", "",
               "| capture | frames | template vertices | template to frame (cm) | frame to template (cm) | jitter (mm) "
               "| s/frame |", "|---|---|---|---|---|---|---|"]
        for label, m in real:
            md.append("| %s | %d | %d | %s | %s | %.2f | %.2f |" % (
                label, m["frames"], m["template_vertices"], cm(m["mean_surface_distance_m"]),
                cm(m["mean_coverage_distance_m"]), 1000 * m["mean_jitter_m"], m["seconds_per_frame"]))
        md.append("")
    if ablations:
        md += ["### Ablations (samba)", "", "| variant | template frame | mean (cm) | < 10 cm (%) | fit s/frame |",
               "|---|---|---|---|---|"]
        for label, m in ablations:
            md.append("| %s | %d | %s | %s | %.2f |" % (label, m["template_frame"], cm(m["mean_vertex_error_m"]),
                                                      pct(m["within_10cm"]), per_frame(m, "fit")))
        md.append("")
    if criteria:
        md += ["### Template criterion", "",
               "After the topological criteria (most persistent shells, then smallest genus), the default takes the "
               "frame whose fitted body is nearest the rest pose; the paper takes the most uniform vertex areas "
               "(`--template-criterion area-ratio`). Template frame, mean error (cm), within 10 cm (%):", "",
               "| sequence | rest pose (default) | area ratio (paper) |", "|---|---|---|"]
        for label, pose_run, area_run in criteria:
            md.append("| %s | %s | %s |" % (label, *("%d: %s / %s" % (m["template_frame"], cm(m["mean_vertex_error_m"]),
                                                                     pct(m["within_10cm"]))
                                                    for m in (pose_run, area_run))))
        md.append("")
    md += ["### Speed per stage (seconds per frame)", ""]
    md += stage_table(([per_frame_run] if per_frame_run else []) + accuracy[1:2] + real[:1], "sequence") + [""]
    md += ["### Scaling with template size (dress-walk, %d frames, capture voxel size varied)" % size_frames, ""]
    md += stage_table(sizes, "capture") + [""]
    md += ["### Scaling with sequence length (dress-walk)", ""]
    md += stage_table(lengths, "length") + [""]
    md += ["### Threads (dress-walk, %d frames)" % thread_frames, ""]
    md += stage_table(threads, "threads") + [""]
    target_rows = [m for _, m in sizes + lengths + ([per_frame_run] if per_frame_run else [])
                   if 8000 <= m["template_vertices"] <= 12000]
    md += ["### Targets", ""]
    if target_rows:
        best = min(target_rows, key=lambda m: m["seconds_per_frame"])
        md.append("- Whole pipeline <= 0.5 s per frame for a 10k-vertex template on 2 cores: measured %.2f s per "
                  "frame (%s, %d vertices): %s." % (best["seconds_per_frame"], best["name"], best["template_vertices"],
                                                    "met" if best["seconds_per_frame"] <= 0.5 else "not met"))
    if len(lengths) > 1:
        first, last = lengths[0][1], lengths[-1][1]
        slope = (last["peak_rss_mb"] - first["peak_rss_mb"]) / max(1, last["frames"] - first["frames"])
        md.append("- Memory independent of sequence length: peak %.0f MB for %d frames, %.0f MB for %d frames, "
                  "%.2f MB more per frame (the input frames are held in memory): %s."
                  % (first["peak_rss_mb"], first["frames"], last["peak_rss_mb"], last["frames"], slope,
                     "nearly flat, not strictly met" if slope > 0.05 else "met"))
    md.append("")
    image_dir = "bench/results" if update else str(out)
    md += ["![%s](%s/%s)" % (name, image_dir, name) for name in images] + [""]
    md += ["Commands (paths relative to the repository; `out/...` is the working folder):", "", "```"]
    # Commands name the working folder relative to the repository; one given elsewhere (--out) is
    # shown as the default one, so that the listed commands read the same.
    relative_out = os.path.relpath(out, ROOT)
    default_out = "out/bench-" + mode
    md += [c.replace(relative_out, default_out) for c in bench.commands] + ["```", "", END]
    text = "\n".join(md) + "\n"
    (out / "benchmarks.md").write_text(text)
    results = {"machine": info, "mode": mode, "seconds": elapsed,
               "runs": {m["name"]: {k: v for k, v in m.items() if not k.startswith("per_frame") and k != "files"}
                        for _, m in accuracy + ablations + real + sizes + lengths + threads
                        + [(None, area_run) for _, _, area_run in criteria]}}
    (out / "results.json").write_text(json.dumps(results, indent=2) + "\n")
    log("wrote %s" % (out / "benchmarks.md"))
    if update:
        results_dir = ROOT / "bench" / "results"
        results_dir.mkdir(exist_ok=True)
        for name in images:
            shutil.copyfile(out / name, results_dir / name)
        benchmarks = ROOT / "BENCHMARKS.md"
        current = benchmarks.read_text()
        if BEGIN in current and END in current:
            current = current[: current.index(BEGIN)] + text.rstrip("\n") + current[current.index(END) + len(END):]
        else:
            current = current.rstrip("\n") + "\n\n" + text
        benchmarks.write_text(current)
        log("updated %s and %s" % (benchmarks, results_dir))
    print(text)


if __name__ == "__main__":
    main()
