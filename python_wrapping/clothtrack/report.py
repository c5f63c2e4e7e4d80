"""The report of an aligned sequence: plots, renders and an HTML page beside `clothtrack align`'s output.

usage: python3 -m clothtrack.report OUT   (OUT holds metrics.json and aligned.pvd; needs an X
display for the renders; without one it starts a virtual one of its own)

Writes OUT/images/per_frame_error.png, cumulative_error.png, confidence.png (each frame's
ground-truth-free confidence and body distance, doubtful frames marked), frame_NNNN.png (input frame, template,
result coloured by error), correspondence_NNNN.png (a colour field on the template carried to the frame),
body_NNNN.png (the fitted body inside the frame, from OUT/body_fit.json) and OUT/report.html.
"""
import html
import json
import os
import sys
from pathlib import Path

from .virtual_display import VirtualDisplayError, ensure_display


def _plots(metrics, images):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    written = []
    frames = metrics["frame_numbers"]
    has_truth = "per_frame_mean_error_m" in metrics
    fig, ax = plt.subplots(figsize=(7, 3.2), dpi=110)
    if has_truth:
        ax.plot(frames, [100 * e for e in metrics["per_frame_mean_error_m"]], label="mean")
        ax.plot(frames, [100 * e for e in metrics["per_frame_p90_error_m"]], label="90th percentile",
                alpha=0.7)
        if "per_frame_marker_error_m" in metrics:
            ax.plot(frames, [100 * e if e is not None else float("nan")
                             for e in metrics["per_frame_marker_error_m"]], label="markers (mean)", alpha=0.7)
        ax.set_ylabel("vertex error (cm)")
    else:
        ax.plot(frames, [100 * e for e in metrics["per_frame_surface_distance_m"]],
                label="template to frame")
        ax.plot(frames, [100 * e for e in metrics["per_frame_coverage_distance_m"]],
                label="frame to template")
        ax.set_ylabel("mean distance (cm)")
    ax.axvline(frames[metrics["template_frame"]], color="grey", linestyle=":", label="template frame")
    ax.set_xlabel("frame")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(images / "per_frame_error.png")
    plt.close(fig)
    written.append("per_frame_error.png")
    curves = [(key, label) for key, label in (("cumulative_error", "all vertices"),
                                              ("marker_cumulative_error", "markers (nearest vertex)"))
              if key in metrics]
    if curves:
        fig, ax = plt.subplots(figsize=(5, 3.2), dpi=110)
        for key, label in curves:
            curve = metrics[key]
            ax.plot([100 * t for t in curve["threshold_m"]], [100 * f for f in curve["fraction"]], label=label)
        ax.set_xlabel("error threshold (cm)")
        ax.set_ylabel("within the threshold (%)")
        ax.legend(fontsize=8)
        ax.set_ylim(0, 100)
        ax.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig(images / "cumulative_error.png")
        plt.close(fig)
        written.append("cumulative_error.png")
    return written


def _chosen_frames(metrics):
    n = metrics["frames"]
    picks = [metrics["template_frame"], n // 2, n - 1]
    if "worst_frame" in metrics:
        picks.append(metrics["worst_frame"])
    return sorted(set(picks))


def _render_frame(out, metrics, k, path, error_range):
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

    from clothtrack.rendering import colour_actor
    from clothtrack.sequence import read_sequence

    number = metrics["frame_numbers"][k]
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(str(out / "aligned" / ("aligned_%04d.vtp" % number)))
    reader.Update()
    result = reader.GetOutput()
    conventions = {"length_unit": metrics["unit"], "up_axis": metrics["up"]}
    frame = read_sequence(metrics["files"][k], **conventions)[0]
    template = read_sequence(metrics["files"][metrics["template_frame"]], **conventions)[0]
    panels = [("input frame %d" % number, colour_actor(frame, (0.85, 0.85, 0.85), smooth_normals=True)),
              ("template (frame %d)" % metrics["frame_numbers"][metrics["template_frame"]],
               colour_actor(template, (0.86, 0.72, 0.62), smooth_normals=True))]
    coloured, bar, label = error_actor(result, error_range)
    panels.append(("aligned template, %s" % label.split(" (")[0], coloured))
    _save_panels(panels, path, bar)


def error_actor(result, error_range):
    """An aligned frame coloured by its per-vertex Error (SurfaceDistance without a ground truth),
    blue at 0 to red at `error_range` metres: (actor, scalar bar, the bar's title)."""
    from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

    array = "Error" if result.GetPointData().GetArray("Error") else "SurfaceDistance"
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(result)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray(array)
    mapper.SetScalarRange(0.0, error_range)
    lut = mapper.GetLookupTable()
    lut.SetHueRange(0.66, 0.0)
    lut.Build()
    actor = vtkActor()
    actor.SetMapper(mapper)
    label = "error (m)" if array == "Error" else "distance to frame (m)"
    bar = vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle(label)
    bar.SetNumberOfLabels(6)
    bar.SetWidth(0.12)
    bar.SetHeight(0.6)
    bar.SetPosition(0.85, 0.2)
    bar.GetTitleTextProperty().SetColor(0, 0, 0)
    bar.GetLabelTextProperty().SetColor(0, 0, 0)
    bar.SetLabelFormat("%.2f")
    return actor, bar, label


def _save_panels(panels, path, bar=None):
    """Draws (title, actor or list of actors) panels side by side, each framed on its first actor (the
    template frame may be elsewhere in the room), with `bar` in the last one, and writes the PNG."""
    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkTextActor

    from clothtrack.rendering import offscreen_window, save_png

    window = offscreen_window(1200, 560)
    for index, (title, actors) in enumerate(panels):
        actors = actors if isinstance(actors, (list, tuple)) else [actors]
        actor = actors[0]
        renderer = vtkRenderer()
        renderer.SetViewport(index / len(panels), 0, (index + 1) / len(panels), 1)
        renderer.SetBackground(1, 1, 1)
        for each in actors:
            renderer.AddActor(each)
        text = vtkTextActor()
        text.SetInput(title)
        text.GetTextProperty().SetColor(0, 0, 0)
        text.GetTextProperty().SetFontSize(16)
        text.SetPosition(10, 530)
        renderer.AddActor2D(text)
        if bar is not None and index == len(panels) - 1:
            renderer.AddActor2D(bar)
        bounds = actor.GetBounds()
        centre = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (bounds[4] + bounds[5]) / 2]
        camera = renderer.GetActiveCamera()
        camera.SetFocalPoint(*centre)
        camera.SetPosition(centre[0] + 1.2, centre[1] + 0.5, centre[2] + 3.2)
        camera.SetViewUp(0, 1, 0)
        renderer.ResetCamera(bounds)
        camera.Zoom(1.15)
        window.AddRenderer(renderer)
    save_png(window, path)


def _render_correspondence(out, metrics, k, path):
    """A smooth colour field on the template (its position at the template frame), carried by the
    alignment to frame k, and from there to the input frame's own vertices (nearest aligned vertex):
    the dense correspondence the alignment makes (paper Figures 4 and 5)."""
    import numpy as np
    from vtkmodules.util import numpy_support
    from vtkmodules.vtkCommonDataModel import vtkStaticPointLocator
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

    from clothtrack.rendering import colour_field_actor
    from clothtrack.sequence import read_sequence

    def aligned_frame(index):
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(str(out / "aligned" / ("aligned_%04d.vtp" % metrics["frame_numbers"][index])))
        reader.Update()
        return reader.GetOutput()

    j = metrics["template_frame"]
    template, result = aligned_frame(j), aligned_frame(k)
    frame = read_sequence(metrics["files"][k], length_unit=metrics["unit"], up_axis=metrics["up"])[0]
    points = numpy_support.vtk_to_numpy(template.GetPoints().GetData())
    low, high = points.min(0), points.max(0)
    rgb = (255 * (0.15 + 0.85 * (points - low) / np.maximum(high - low, 1e-9))).astype(np.uint8)
    locator = vtkStaticPointLocator()
    locator.SetDataSet(result)
    locator.BuildLocator()
    frame_points = numpy_support.vtk_to_numpy(frame.GetPoints().GetData())
    nearest = np.array([locator.FindClosestPoint(p) for p in frame_points], dtype=np.int64)

    number = metrics["frame_numbers"]
    panels = [("template (frame %d)" % number[j], colour_field_actor(template, rgb)),
              ("aligned template, frame %d" % number[k], colour_field_actor(result, rgb)),
              ("input frame %d, nearest aligned vertex" % number[k], colour_field_actor(frame, rgb[nearest]))]
    _save_panels(panels, path)


def _render_body(out, metrics, k, path):
    """The body fitted under the clothing of frame k (stage 1), alone and inside the translucent
    frame (paper Figure 2). Returns False when the run has no body fit (OUT/body_fit.json)."""
    import clothtrack
    from clothtrack.rendering import colour_actor
    from clothtrack.sequence import read_sequence

    summary_path = out / "body_fit.json"
    if not summary_path.is_file():
        return False
    summary = json.loads(summary_path.read_text())
    pose = summary["per_frame"][k]
    source = clothtrack.ctBodyModelSource()
    if summary.get("model"):
        source.SetModelFileName(summary["model"])
    for index, value in enumerate(summary["beta"]):
        source.SetShapeCoefficient(index, value)
    for joint, rotation in enumerate(pose["rotations"]):
        source.SetJointRotation(joint, *rotation)
    source.SetTranslation(*pose["translation"])
    source.Update()
    body = source.GetOutput()
    frame = read_sequence(metrics["files"][k], length_unit=metrics["unit"], up_axis=metrics["up"])[0]
    number = metrics["frame_numbers"][k]
    skin = (0.93, 0.62, 0.45)
    panels = [("input frame %d" % number, colour_actor(frame, (0.85, 0.85, 0.85), smooth_normals=True)),
              ("fitted body (%s)" % pose["status"], colour_actor(body, skin, smooth_normals=True)),
              ("fitted body inside the frame",
               [colour_actor(frame, (0.6, 0.7, 0.85), opacity=0.3, smooth_normals=True),
                colour_actor(body, skin, smooth_normals=True)])]
    _save_panels(panels, path)
    return True


def _confidence_plot(metrics, images):
    """Each frame's confidence (1: every measure within its limit) and its distance to the template posed by
    its fitted body, the doubtful frames marked; None when metrics.json has no confidence."""
    if "per_frame_confidence" not in metrics:
        return None
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    frames = metrics["frame_numbers"]
    doubtful = [d["frame"] for d in metrics.get("doubtful_frames", [])]
    fig, ax = plt.subplots(figsize=(7, 3.2), dpi=110)
    ax.plot(frames, metrics["per_frame_confidence"], label="confidence")
    ax.scatter([frames[k] for k in doubtful], [metrics["per_frame_confidence"][k] for k in doubtful],
               color="red", s=12, zorder=3, label="doubtful")
    ax.set_ylim(-0.05, 1.05)
    ax.set_ylabel("confidence")
    ax.set_xlabel("frame")
    ax.grid(alpha=0.3)
    handles, labels = ax.get_legend_handles_labels()
    if "per_frame_body_distance_m" in metrics:
        twin = ax.twinx()
        line, = twin.plot(frames, [100 * d if d is not None else float("nan")
                                   for d in metrics["per_frame_body_distance_m"]], color="grey", alpha=0.7)
        twin.set_ylabel("body distance (cm)")
        handles.append(line)
        labels.append("distance to the body-posed template")
    ax.legend(handles, labels, fontsize=8)
    fig.tight_layout()
    fig.savefig(images / "confidence.png")
    plt.close(fig)
    return "confidence.png"


def _confidence_section(metrics, image):
    """The doubtful and the retried frames, each with what was found and done."""
    if "per_frame_confidence" not in metrics:
        return []
    doubtful = metrics.get("doubtful_frames", [])
    retried = metrics.get("retried_frames", [])
    parts = ["<h2>Confidence (without ground truth)</h2>",
             "<p>%d of %d frames are doubtful; %d were fitted again from other starts.</p>"
             % (len(doubtful), metrics["frames"], len(retried))]
    if image:
        parts.append('<img src="images/%s" alt="%s">' % (image, image))
    if doubtful:
        parts.append(_table([("frame %d" % metrics["frame_numbers"][d["frame"]],
                              "%s: %s" % (os.path.basename(d["file"]), d["doubt"])) for d in doubtful]))
    if retried:
        parts.append(_table([("frame %d retried" % metrics["frame_numbers"][r["frame"]],
                              "%d attempts, kept %s (severity %.2f)" % (r["attempts"], r["kept"], r["severity"]))
                             for r in retried]))
    return parts


def _choice_rows(entries, kept, label):
    """One row per alignment of a choice: its label (the kept one marked), figures and folder."""
    rows = []
    for i, entry in enumerate(entries):
        figures = "mean stretch %.4f, surface distance %.2f mm" % (entry["mean_stretch"],
                                                                   1000 * entry["mean_surface_distance_m"])
        if "mean_vertex_error_m" in entry:
            figures += ", mean vertex error %.2f cm" % (100 * entry["mean_vertex_error_m"])
        rows.append(("%s%s" % (label(entry), " (kept)" if i == kept else ""), "%s; %s" % (figures, entry["folder"])))
    return rows


def _model_section(metrics):
    """Which body model the alignment was kept under, and every model's figures
    (`align --model A --model B`)."""
    choice = metrics.get("model_choice")
    if not choice:
        return []
    rows = _choice_rows(choice["models"], choice["kept"], lambda m: m["model"])
    return ["<h2>Body model</h2>",
            "<p>Aligned under %d body models; kept: %s (%s).</p>"
            % (len(choice["models"]), html.escape(metrics["model"]), html.escape(choice["criterion"])),
            _table(rows)]


def _template_section(metrics):
    """Which template frame the alignment was kept under, and every candidate's figures (a
    collection of poses, or `align --template-candidates N`)."""
    choice = metrics.get("template_choice")
    if not choice:
        return []
    rows = _choice_rows(choice["candidates"], choice["kept"], lambda c: "template frame %d" % c["template_frame"])
    return ["<h2>Template frame</h2>",
            "<p>Aligned under %d template frames; kept: frame %d (%s).</p>"
            % (len(choice["candidates"]), choice["kept_template_frame"], html.escape(choice["criterion"])),
            _table(rows)]


def _table(rows):
    cells = "".join("<tr><th>%s</th><td>%s</td></tr>" % (html.escape(k), html.escape(v)) for k, v in rows)
    return "<table>%s</table>" % cells


def write_report(out):
    """Writes OUT/images/*.png and OUT/report.html from OUT/metrics.json and OUT/aligned/."""
    out = Path(out)
    metrics_path = out / "metrics.json"
    if not metrics_path.is_file():
        raise FileNotFoundError("%s: no metrics.json (run 'clothtrack align' first)" % out)
    metrics = json.loads(metrics_path.read_text())
    images = out / "images"
    images.mkdir(exist_ok=True)
    plots = _plots(metrics, images)
    error_range = 0.1 if "mean_vertex_error_m" in metrics else 0.05
    renders = []
    for k in _chosen_frames(metrics):
        name = "frame_%04d.png" % metrics["frame_numbers"][k]
        _render_frame(out, metrics, k, images / name, error_range)
        renders.append((k, name))
        if k != metrics["template_frame"]:
            name = "correspondence_%04d.png" % metrics["frame_numbers"][k]
            _render_correspondence(out, metrics, k, images / name)
            renders.append((k, name))
        name = "body_%04d.png" % metrics["frame_numbers"][k]
        if _render_body(out, metrics, k, images / name):
            renders.append((k, name))

    rows = [("input", metrics["input"]), ("frames", str(metrics["frames"])),
            ("template frame", "%d (%s)" % (metrics["template_frame"], os.path.basename(metrics["template_file"]))),
            ("template vertices", str(metrics["template_vertices"])),
            ("time", "%.1f s in all, %.2f s per frame, %d threads" % (
                metrics["seconds_total"], metrics["seconds_per_frame"], metrics["threads"])),
            ("peak memory", "%.0f MB" % metrics["peak_rss_mb"])]
    rows += [("stage: " + k, "%.1f s" % v) for k, v in metrics["stage_seconds"].items()]
    if "mean_vertex_error_m" in metrics:
        rows += [("mean vertex error", "%.2f cm" % (100 * metrics["mean_vertex_error_m"])),
                 ("median vertex error", "%.2f cm" % (100 * metrics["median_vertex_error_m"])),
                 ("90th percentile", "%.2f cm" % (100 * metrics["p90_vertex_error_m"])),
                 ("within 5 cm", "%.2f %%" % (100 * metrics["within_5cm"])),
                 ("within 10 cm", "%.2f %%" % (100 * metrics["within_10cm"])),
                 ("worst frame", "%d (mean %.2f cm)" % (metrics["worst_frame"],
                                                       100 * metrics["worst_frame_mean_error_m"])),
                 ("drift", "%.3f mm per frame from the template" % (1000 * metrics["drift_m_per_frame"]))]
    if "marker_mean_error_m" in metrics:
        worst = max(metrics["per_marker_mean_error_m"].items(), key=lambda item: item[1], default=("-", 0.0))
        rows += [("marker error", "%.2f cm mean, %.2f %% within 5 cm, %.2f %% within 10 cm"
                  % (100 * metrics["marker_mean_error_m"], 100 * metrics["marker_within_5cm"],
                     100 * metrics["marker_within_10cm"])),
                 ("worst marker", "%s (mean %.2f cm)" % (worst[0], 100 * worst[1]))]
    rows += [("template to frame surface", "%.2f cm (mean)" % (100 * metrics["mean_surface_distance_m"])),
             ("frame to template surface", "%.2f cm (mean)" % (100 * metrics["mean_coverage_distance_m"])),
             ("jitter", "%.2f mm (mean vertex acceleration per frame)" % (1000 * metrics["mean_jitter_m"]))]
    body = ["<h1>ClothTrack alignment report</h1>", _table(rows), "<h2>Per frame</h2>"]
    body += ['<img src="images/%s" alt="%s">' % (p, p) for p in plots]
    body += _model_section(metrics)
    body += _template_section(metrics)
    body += _confidence_section(metrics, _confidence_plot(metrics, images))
    body.append("<h2>Frames</h2>")
    shown = set()
    for k, name in renders:
        if k not in shown:
            body.append("<h3>frame %d</h3>" % metrics["frame_numbers"][k])
            shown.add(k)
        body.append("<img src=\"images/%s\" alt=\"%s\">" % (name, name))
    page = ("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>ClothTrack report</title>"
            "<style>body{font-family:sans-serif;max-width:1240px;margin:auto}th{text-align:left;"
            "padding-right:2em}img{max-width:100%}</style></head><body>\n"
            + "\n".join(body) + "\n</body></html>\n")
    part = out / "report.html.part"
    part.write_text(page)
    part.replace(out / "report.html")
    return out / "report.html"


def main(argv):
    if len(argv) != 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) == 2 else 1
    try:
        with ensure_display():
            path = write_report(argv[1])
    except (OSError, KeyError, ValueError, VirtualDisplayError) as error:
        print("clothtrack report: %s" % error, file=sys.stderr)
        return 1
    print("wrote", path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
