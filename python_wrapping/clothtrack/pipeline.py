"""The whole pipeline in one call: clothtrack.align(frames, ...)."""

import os
import time

import numpy as np
from vtkmodules.util import numpy_support

from .sequence import _ErrorCatcher, read_sequence

_BUILTIN_MODEL = "builtin"  # the model named as on the command line (--model builtin)


class Alignment:
    """The result of align(): one template mesh deformed through the sequence.

    aligned         list of vtkPolyData, one per frame, all with the template's connectivity and
                    the point arrays Displacement, CorrespondenceUsed, SurfaceDistance (and Error
                    with a ground truth)
    positions       numpy array (frames, vertices, 3): the aligned vertex positions
    faces           numpy array (triangles, 3): the template's triangles
    template_frame  index of the frame the template was taken from
    errors          numpy array (frames, vertices) of vertex errors in metres (NaN where a vertex has
                    no ground truth), or None without a ground truth
    metrics         dict with the keys of the app's metrics.json: frames, template_frame,
                    mean_surface_distance_m and, with a ground truth, mean_vertex_error_m,
                    median_vertex_error_m, p90_vertex_error_m, max_vertex_error_m, within_5cm,
                    within_10cm, worst_frame, drift_m_per_frame, per_frame_mean_error_m (from
                    ctAlignmentError: the template frame is left out of the pooled figures, as in
                    the app); always per_frame_confidence, per_frame_coverage_distance_m,
                    per_frame_fit_attempts, per_frame_body_distance_m and per_frame_extent_gap_m
                    (None where the frame's body is not trusted) and doubtful_frames (frames with
                    a confidence below 1; the fit stage warns about each), seconds_total,
                    template_frames_by_pose (when the rest pose chose the template); with several
                    body models also model and model_choice, with several template frames
                    template_choice and template_criterion, as in metrics.json
    model           the body model it was made under: "builtin" or the model file as named
    model_alignments  every model's Alignment, in the order the models were named (this one among
                    them); [self] under one model
    template_alignments  every template candidate's Alignment (this one among them), the frame
                    chosen first; [self] under one template frame
    body_fit        the ctBodyFit the alignment was made with (updated)
    summary         the template fit's per-frame vtkTable (ctTemplateFit output port 1)
    """

    def __init__(self, aligned, template_frame, errors=None, frame_errors=None, fit_summary=None):
        self.aligned = aligned
        self.template_frame = template_frame
        self.positions = np.stack([numpy_support.vtk_to_numpy(a.GetPoints().GetData()) for a in aligned])
        self.faces = numpy_support.vtk_to_numpy(aligned[0].GetPolys().GetConnectivityArray()).reshape(-1, 3)
        self.errors = errors
        self.model = _BUILTIN_MODEL
        self.model_alignments = [self]
        self.template_alignments = [self]
        self.body_fit = None
        self.summary = fit_summary
        distances = [numpy_support.vtk_to_numpy(a.GetPointData().GetArray("SurfaceDistance")) for a in aligned]
        self.metrics = {
            "frames": len(aligned),
            "template_frame": template_frame,
            "mean_surface_distance_m": float(np.mean([d.mean() for d in distances])),
        }
        if fit_summary is not None:  # ctTemplateFit's per-frame table: each frame's confidence
            def column(name):
                return [fit_summary.GetValueByName(k, name).ToDouble() for k in range(fit_summary.GetNumberOfRows())]

            self.metrics["per_frame_confidence"] = column("Confidence")
            self.metrics["per_frame_coverage_distance_m"] = column("CoverageDistance")
            self.metrics["per_frame_fit_attempts"] = [int(a) for a in column("Attempts")]
            self.metrics["per_frame_body_distance_m"] = [None if np.isnan(d) else d for d in column("BodyDistance")]
            self.metrics["per_frame_extent_gap_m"] = [None if np.isnan(d) else d for d in column("ExtentGap")]
            self.metrics["doubtful_frames"] = [k for k, c in enumerate(self.metrics["per_frame_confidence"]) if c < 1.0]
        if frame_errors is not None:  # ctAlignmentError's per-frame table and its sequence figures
            sequence = frame_errors.GetFieldData()

            def value(name):
                return sequence.GetArray(name).GetTuple1(0)

            self.metrics.update({
                "mean_vertex_error_m": value("SequenceMean"),
                "median_vertex_error_m": value("SequenceMedian"),
                "p90_vertex_error_m": value("SequenceP90"),
                "max_vertex_error_m": value("SequenceMax"),
                "within_5cm": value("SequenceWithin5cm"),
                "within_10cm": value("SequenceWithin10cm"),
                "worst_frame": int(value("WorstFrame")),
                "drift_m_per_frame": value("DriftPerFrame"),
                "per_frame_mean_error_m": [frame_errors.GetValueByName(k, "Mean").ToDouble()
                                           for k in range(frame_errors.GetNumberOfRows())],
            })


def _as_sequence(frames, frame_rate):
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet

    if isinstance(frames, vtkMultiBlockDataSet):
        return frames
    if isinstance(frames, (str, bytes)) or hasattr(frames, "__fspath__"):
        frames = read_sequence(frames, frame_rate=frame_rate)
    sequence = vtkMultiBlockDataSet()
    for k, frame in enumerate(frames):
        sequence.SetBlock(k, frame)
    if sequence.GetNumberOfBlocks() == 0:
        raise ValueError("align: no frames")
    return sequence


# Keywords of align() that set a filter property of the same name (CamelCase); None keeps the
# filter's default, which is the core's (docs/parameters.md).
_STAGE_KEYWORDS = {
    "body": ("samples", "temporal_weight", "root_temporal_weight", "leg_temporal_weight",
             "leg_raise_start", "stature_start", "outside_tolerance", "inside_tolerance",
             "register_frames", "limb_restarts", "two_shapes",
             "same_shape_tolerance"),
    "correspondence": ("epsilon", "minimum_radius", "maximum_radius", "minimum_seed_consensus",
                       "minimum_shell_area", "persistence"),
    "fit": ("solver_tolerance", "intermediate_tolerance", "refactor_steps", "nearest_reuse",
            "maximum_nearest_distance", "coverage_weight", "start_from_body",
            "stretch_start_to_frame", "correspondence_gate", "landmark_consensus"),
    "error": ("maximum_truth_distance",),
    "selection": ("minimum_shell_area", "persistence"),
}

def _property_name(keyword):
    return "".join(word.capitalize() for word in keyword.split("_"))


def _set_stage_keywords(stage, algorithm, options):
    for keyword in _STAGE_KEYWORDS[stage]:
        value = options.get(keyword)
        if value is not None:
            getattr(algorithm, "Set" + _property_name(keyword))(value)


def _model_label(model):
    return _BUILTIN_MODEL if model is None else str(model)


def _models_of(model):
    """The body models named by align()'s `model` keyword, as a list of labels."""
    models = list(model) if isinstance(model, (list, tuple)) else [model]
    if not models:
        raise ValueError("model: an empty list names no body model")
    labels = [_model_label(m) for m in models]
    for label in labels:
        if label != _BUILTIN_MODEL and not os.path.isfile(label):
            raise FileNotFoundError("%s: no such body model file" % label)
    return labels


def align(frames, ground_truth=None, template_frame=None, solver="exact", predict_radius=0.3,
          shape_frames=8, frame_rate=25.0, progress=None, template_criterion="rest-pose",
          threads=0, model=None, template_candidates=0, **options):
    """Aligns a captured sequence: body fit and landmarks, template choice, geodesic-patch
    correspondences, template fit and, with a ground truth, the vertex errors.

    frames          a folder, glob pattern or list file of frames (see read_sequence), a list of
                    vtkPolyData, or a vtkMultiBlockDataSet with one frame per block
    ground_truth    the same kinds of input: a sequence with one connectivity, same frame count
    template_frame  a frame index to use as the template, or None to choose it automatically
    template_criterion  the automatic choice's last criterion after the topology: "rest-pose" (the
                    fitted body closest to the rest pose) or "area-ratio" (the paper's)
    solver          "exact" (sparse Cholesky, the default) or "lbfgs" (the paper's solver)
    predict_radius  width (metres) of the landmark-driven start of the frames whose body fit is
                    doubtful (of every frame with start_from_body=False); 0 starts them from
                    their neighbour's fit unchanged, as the paper does
    progress        optional callable(stage_name, fraction) called as the stages advance:
                    "body fit", "template selection" (when template_frame is None),
                    "correspondence", "template fit", "alignment error" (with a ground truth)
    threads         threads of each stage (0: every core)
    model           the body model: None or "builtin" (the built-in model), a model file (.vtp,
                    `clothtrack body-model`, `clothtrack import-makehuman`), or a list of these.
                    With a list the sequence is aligned under each, and the alignment kept as
                    `clothtrack align --model A --model B` keeps it (ctModelChoice, no ground
                    truth): the first, unless others are both less stretched and closer to
                    the frames than it; then the one that gains most. The result's metrics then
                    hold "model" and "model_choice" as the app's metrics.json does, and
                    model_alignments holds every model's Alignment. Stage names in progress
                    calls and errors then start with the model, e.g. "mh.vtp: body fit".
    template_candidates  template frames to align under when template_frame is None: the one
                    chosen, then the next ones by pose (the fitted body nearest the rest pose),
                    one alignment kept by the same figures as among body models (no ground
                    truth), as `clothtrack align --template-candidates N` does. 0 (default): 3 on
                    a collection of unrelated poses (at least half of the frames do not continue
                    their predecessor), 1 on a sequence. With more than one the result's metrics
                    hold "template_choice" as metrics.json does, template_alignments every
                    candidate's Alignment, and stage names start with "template frame K: " for
                    the candidates after the first.
    options         further parameters by their snake_case names (docs/parameters.md), e.g.
                    epsilon=0.2, minimum_radius=0.05, minimum_shell_area=0.05, persistence=2,
                    solver_tolerance=1e-5, maximum_truth_distance=0.05, start_from_body=False
                    (each frame starts from its neighbour's fit instead of the template posed
                    by the frame's fitted body)

    Returns an Alignment. Raises RuntimeError with the stage's message when a stage fails.
    """
    if solver not in ("exact", "lbfgs"):
        raise ValueError("solver must be 'exact' or 'lbfgs'")
    if template_criterion not in ("rest-pose", "area-ratio"):
        raise ValueError("template_criterion must be 'rest-pose' or 'area-ratio'")
    known = {keyword for keywords in _STAGE_KEYWORDS.values() for keyword in keywords}
    unknown = sorted(set(options) - known)
    if unknown:
        raise TypeError("align() got unknown keyword(s) %s; known: %s" % (", ".join(unknown),
                                                                          ", ".join(sorted(known))))
    if threads < 0:
        raise ValueError("threads must be 0 (every core) or more")
    if template_candidates < 0:
        raise ValueError("template_candidates must be 0 (automatic) or more")
    models = _models_of(model)
    sequence = _as_sequence(frames, frame_rate)
    if template_frame is not None and not 0 <= template_frame < sequence.GetNumberOfBlocks():
        raise ValueError("template_frame %d is not a frame (0..%d)" % (template_frame,
                                                                        sequence.GetNumberOfBlocks() - 1))
    truth = None
    if ground_truth is not None:
        truth = _as_sequence(ground_truth, frame_rate)
        if truth.GetNumberOfBlocks() != sequence.GetNumberOfBlocks():
            raise ValueError("the ground truth has %d frames, the sequence %d"
                             % (truth.GetNumberOfBlocks(), sequence.GetNumberOfBlocks()))
    settings = dict(template_frame=template_frame, solver=solver, predict_radius=predict_radius,
                    shape_frames=shape_frames, progress=progress,
                    template_criterion=template_criterion, threads=threads, options=options,
                    template_candidates=template_candidates)
    alignments = [_align_choosing_template(sequence, truth, label, settings,
                                           "%s: " % label if len(models) > 1 else "")
                  for label in models]
    if len(alignments) == 1:
        return alignments[0]
    return _choose_model(alignments)


class _Stages:
    """The named algorithms of one alignment: each one's first error kept and its progress
    reported under its name (prefixed), so that the stages can be updated in several steps."""

    def __init__(self, settings, prefix):
        self.progress = settings["progress"]
        self.prefix = prefix
        self.catchers = {}

    def add(self, name, algorithm):
        name = self.prefix + name
        self.catchers[name] = _ErrorCatcher(algorithm)
        if self.progress is not None:
            progress = self.progress
            algorithm.AddObserver("ProgressEvent", lambda obj, _event: progress(name, obj.GetProgress()))
        return algorithm

    def raise_first_error(self):
        for name, catcher in self.catchers.items():
            if catcher.message:
                raise RuntimeError("%s: %s" % (name, catcher.message))


def _align_choosing_template(sequence, truth, model, settings, prefix):
    """The alignment under the template frame chosen and, on a collection of poses, under the
    next ones by pose (the first alignment's body fit reused), one kept as the app keeps it. The
    template frame is chosen once, by ctTemplateSelection, and handed to every alignment."""
    started = time.monotonic()
    stages = _Stages(settings, prefix)
    body = _body_fit(sequence, model, settings, stages)
    if settings["template_frame"] is not None:
        return _align_under(sequence, truth, model, settings, stages, body, started)
    chosen, by_pose, default_count = _select_template(sequence, body, settings, stages)
    first = _align_under(sequence, truth, model, dict(settings, template_frame=chosen), stages, body,
                         started)
    if settings["template_candidates"] == 1:
        return first
    if by_pose:
        first.metrics["template_frames_by_pose"] = by_pose
    count = settings["template_candidates"] or default_count
    further = [k for k in by_pose if k != first.template_frame][:count - 1]
    if not further:
        return first
    candidates = [first]
    for k in further:
        one = dict(settings, template_frame=k)
        candidates.append(_align_under(sequence, truth, model, one,
                                       _Stages(settings, "%stemplate frame %d: " % (prefix, k)), body,
                                       time.monotonic()))
    return _choose_template(candidates, by_pose)


def _body_fit(sequence, model, settings, stages):
    """The ctBodyFit of `sequence` under body model `model` (a label of _models_of), not yet
    updated; its stages (and the model reader's) join `stages`."""
    import clothtrack

    body = clothtrack.ctBodyFit()
    body.SetInputData(sequence)
    body.SetShapeFrames(min(settings["shape_frames"], sequence.GetNumberOfBlocks()))
    if model != _BUILTIN_MODEL:
        reader = stages.add("body model", clothtrack.ctBodyModelReader())
        reader.SetFileName(model)
        body.SetBodyModelConnection(reader.GetOutputPort())
    _set_stage_keywords("body", body, settings["options"])
    body.SetNumberOfThreads(settings["threads"])
    return stages.add("body fit", body)


def _select_template(sequence, body, settings, stages):
    """The template frame ctTemplateSelection chooses (the body fit updated first), the frames the
    rest-pose criterion would choose in turn (empty when it did not decide), and how many
    template frames to try when none is asked for (3 on a collection of unrelated poses, 1 on a
    sequence)."""
    import clothtrack

    selection = stages.add("template selection", clothtrack.ctTemplateSelection())
    selection.SetInputData(0, sequence)
    selection.SetInputConnection(1, body.GetOutputPort(1))
    selection.SetTemplateCriterion(1 if settings["template_criterion"] == "rest-pose" else 0)
    selection.SetNumberOfThreads(settings["threads"])
    _set_stage_keywords("selection", selection, settings["options"])
    selection.Update()
    stages.raise_first_error()
    table = selection.GetCriteriaOutput()
    order = {}
    for row in range(table.GetNumberOfRows()):
        place = table.GetValueByName(row, "PoseOrder").ToInt()
        if place >= 0:
            order[place] = table.GetValueByName(row, "Frame").ToInt()
    fields = selection.GetOutput().GetFieldData()
    chosen = int(fields.GetArray("TemplateFrame").GetTuple1(0))
    default_count = int(fields.GetArray("DefaultTemplateCandidates").GetTuple1(0))
    return chosen, [order[place] for place in sorted(order)], default_count


def _align_under(sequence, truth, model, settings, stages, body, started):
    """One alignment of `sequence` under body model `model` (a label of _models_of) and the
    template frame settings["template_frame"]; `body` is its ctBodyFit (updated or not), the new
    stages join `stages`, and its seconds count from `started` (time.monotonic())."""
    import clothtrack

    options = settings["options"]
    correspondence = stages.add("correspondence", clothtrack.ctPatchCorrespondence())
    correspondence.SetInputData(0, sequence)
    correspondence.SetInputConnection(1, body.GetOutputPort(1))
    correspondence.SetTemplateCriterion(1 if settings["template_criterion"] == "rest-pose" else 0)
    _set_stage_keywords("correspondence", correspondence, options)
    correspondence.SetTemplateFrame(settings["template_frame"])
    fit = stages.add("template fit", clothtrack.ctTemplateFit())
    fit.SetInputData(0, sequence)
    fit.SetInputConnection(1, correspondence.GetOutputPort(0))
    fit.SetInputConnection(2, body.GetOutputPort(1))
    fit.SetInputConnection(3, body.GetOutputPort(0))
    fit.SetSolver(fit.LBFGS if settings["solver"] == "lbfgs" else fit.EXACT)
    fit.SetPredictRadius(settings["predict_radius"])
    _set_stage_keywords("fit", fit, options)
    for algorithm in (correspondence, fit):
        algorithm.SetNumberOfThreads(settings["threads"])
    last = fit
    if truth is not None:
        last = stages.add("alignment error", clothtrack.ctAlignmentError())
        last.SetInputConnection(0, fit.GetOutputPort(0))
        last.SetInputData(1, truth)
        _set_stage_keywords("error", last, options)

    last.Update()
    seconds = time.monotonic() - started
    stages.raise_first_error()

    output = last.GetOutputDataObject(0)
    aligned = [output.GetBlock(k) for k in range(output.GetNumberOfBlocks())]
    summary = fit.GetSummaryOutput()
    if last is fit:
        result = Alignment(aligned, correspondence.GetChosenFrame(), fit_summary=summary)
    else:
        errors = np.stack([numpy_support.vtk_to_numpy(a.GetPointData().GetArray("Error")) for a in aligned])
        result = Alignment(aligned, correspondence.GetChosenFrame(), errors, last.GetFrameErrorOutput(), summary)
    result.model = model
    result.body_fit = body
    result.metrics["seconds_total"] = seconds
    return result


def _preferred(alignments, label):
    """The index ctModelChoice keeps among `alignments`, its criterion, and each alignment's
    entry (its figures, doubtful frames, cost and, with a ground truth, its errors)."""
    import clothtrack

    choice = clothtrack.ctModelChoice()
    for alignment in alignments:
        choice.AddInputDataObject(0, alignment.summary)
    catcher = _ErrorCatcher(choice)
    choice.Update()
    if catcher.message:
        raise RuntimeError("%s: %s" % (label, catcher.message))
    table = choice.GetOutput()
    entries = []
    for i, alignment in enumerate(alignments):
        entry = {"mean_stretch": table.GetValueByName(i, "MeanStretch").ToDouble(),
                 "mean_surface_distance_m": table.GetValueByName(i, "MeanSurfaceDistance").ToDouble(),
                 "doubtful_frames": len(alignment.metrics.get("doubtful_frames", []))}
        for key in ("seconds_total", "mean_vertex_error_m", "within_10cm"):
            if key in alignment.metrics:
                entry[key] = alignment.metrics[key]
        entries.append(entry)
    fields = table.GetFieldData()
    criteria = {name: fields.GetAbstractArray(name).GetValue(0) for name in ("Criterion", "TemplateChoiceCriterion")}
    return choice.GetKeptAlignment(), criteria, entries


def _choose_model(alignments):
    """The alignment kept among the body models', with the choice in its metrics as in
    metrics.json."""
    kept, criteria, entries = _preferred(alignments, "model choice")
    for alignment, entry in zip(alignments, entries):
        entry["model"] = alignment.model
    result = alignments[kept]
    result.metrics["model"] = result.model
    result.metrics["model_choice"] = {"criterion": criteria["Criterion"], "kept": kept, "models": entries}
    result.model_alignments = alignments
    return result


def _choose_template(alignments, by_pose):
    """The alignment kept among the template candidates', with the choice in its metrics as in
    metrics.json (the cost is every candidate's: the later ones reuse the first's body fit)."""
    kept, criteria, entries = _preferred(alignments, "template choice")
    for alignment, entry in zip(alignments, entries):
        entry["template_frame"] = alignment.template_frame
    result = alignments[kept]
    result.metrics["template_choice"] = {
        "criterion": criteria["TemplateChoiceCriterion"], "kept": kept,
        "kept_template_frame": result.template_frame, "candidates": entries}
    result.metrics["template_criterion"] = "alignment-figures"
    result.metrics["template_frames_by_pose"] = by_pose
    result.metrics["seconds_total"] = sum(a.metrics["seconds_total"] for a in alignments)
    result.template_alignments = alignments
    return result
