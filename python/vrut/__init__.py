"""vrut from Python: the virtual wheel-tracking (rutting) test of an asphalt
mixture, run by the same C++ as the command line ``vrut-rutting``.

Every keyword argument is one of vrut-rutting's options, named without its
leading dashes and with ``_`` for ``-`` (``--width-mm 100`` is
``width_mm=100``, ``--E1 4.64`` is ``E1=4.64``, ``--exact-stones`` is
``exact_stones=True``). The options are checked by the command line's own
table: a bad value raises ``ValueError`` with the command line's message.
``vrut.options()`` lists them with their defaults and help (docs/python.md).
"""

import json
import numbers
import os
import signal
import sys
import tempfile

from . import _vrut

__version__ = _vrut.version
__license__ = "BSD-3-Clause"  # LICENSE at the repository's root; docs/licence.md says why it fits the dependencies
__all__ = ["rutting", "specimen", "creep", "options", "Gradation", "Materials", "RuttingRun", "Specimen", "CreepRun",
           "backends"]

# Options that the module sets itself, or that only make sense on a command line.
_RESERVED = {"out": "give out= (the output folder) as the function's own argument",
             "resume": "resume a run with the command line: vrut-rutting --resume DIR",
             "config": "give the options as keyword arguments (or **dict)",
             "help": "see vrut.options()"}


def options(program="rutting"):
    """vrut-rutting's options (or vrut-creep's, program="creep"): a list of
    dicts (name, flag, default, help)."""
    return _vrut.options(program)


def backends():
    """The Kokkos backends of this build ('serial', 'openmp', ...)."""
    return _vrut.backends()


def _text(value):
    # The shortest text that reads back to the same double (repr of a Python
    # float), so the C++ side parses exactly the value given; numpy's
    # scalars as Python's.
    if isinstance(value, bool):
        return str(value)
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))
    return str(value)


class Gradation:
    """A mix's gradation: a built-in one, Gradation(2) (1, 2, 3: docs/method.md),
    or a table, Gradation(sieves_mm=[...], percent_passing=[...], name="mine"),
    checked as the command line checks a gradation file (sieves strictly
    decreasing, 100 % passing the largest, passing not increasing). Give it
    as gradation= to vrut.rutting or vrut.specimen."""

    def __init__(self, builtin=None, *, sieves_mm=None, percent_passing=None, name="gradation"):
        if (builtin is None) == (sieves_mm is None):
            raise TypeError("Gradation(): a built-in number (1, 2, 3) or sieves_mm= with percent_passing=")
        if builtin is not None:
            if not isinstance(builtin, int) or isinstance(builtin, bool):
                raise TypeError(f"Gradation(): the built-in mixes are numbered 1, 2, 3, not {builtin!r}")
            self.builtin = builtin
            self.name, sieves, passing = _vrut.gradation(builtin, [], [], "")
        else:
            if percent_passing is None:
                raise TypeError("Gradation(): sieves_mm= needs percent_passing=")
            if not name or os.sep in name:
                raise ValueError(f"Gradation(): name {name!r}: a plain name, no path")
            self.builtin = None
            self.name, sieves, passing = _vrut.gradation(None, [float(d) for d in sieves_mm],
                                                         [float(p) for p in percent_passing], name)
        self.sieves_mm, self.percent_passing = list(sieves), list(passing)

    def _option(self, path):
        """The --gradation text: the number, or the table written to the CSV file path."""
        if self.builtin is not None:
            return str(self.builtin)
        with open(path, "w") as f:
            f.write("sieve_mm,percent_passing\n")
            for d, p in zip(self.sieves_mm, self.percent_passing):
                f.write(f"{d!r},{p!r}\n")
        return path

    def __repr__(self):
        rows = ", ".join(f"{d:g} mm: {p:g} %" for d, p in zip(self.sieves_mm, self.percent_passing))
        return f"<vrut.Gradation {self.name}: {rows}>"


# The option groups (vrut.options()) that make a Materials.
_MATERIAL_GROUPS = {"Materials", "Numerics", "Loading"}


class Materials:
    """The materials, numerics and loading of a run (vrut-rutting's options
    of those groups: the mastic's Burger's values E1, eta1, E2, eta2, the
    stones, friction, the film, the wheel...), checked now as the command line
    checks them. Give it as materials= to vrut.rutting; keyword arguments
    given beside it win.

        soft = vrut.Materials(eta1=60.0, stone_friction=0.3)
        vrut.rutting(gradation=2, seed=1, materials=soft)
    """

    def __init__(self, **options):
        known = {o["name"]: o for o in _vrut.options("rutting")}
        for key in options:
            o = known.get(key.replace("_", "-"))
            if o is None or o["group"] not in _MATERIAL_GROUPS:
                groups = ", ".join(sorted(_MATERIAL_GROUPS))
                raise TypeError(f"Materials() got an unexpected keyword argument '{key}' (the options of the groups "
                                f"{groups} in vrut.options())")
        _vrut.check("rutting", _arguments("Materials", options))
        self.options = dict(options)

    def __repr__(self):
        return "vrut.Materials(" + ", ".join(f"{k}={v!r}" for k, v in self.options.items()) + ")"


def _arguments(function, kwargs):
    known = {o["name"]: o for o in _vrut.options("creep" if function == "creep" else "rutting")}
    args = []
    for key, value in kwargs.items():
        name = key.replace("_", "-")
        if name in _RESERVED:
            raise TypeError(f"{function}(): {key}: {_RESERVED[name]}")
        if name not in known:
            raise TypeError(f"{function}() got an unexpected keyword argument '{key}' (vrut.options() lists them)")
        if value is None:
            continue
        if known[name]["flag"]:
            if not isinstance(value, bool):
                raise TypeError(f"{function}(): {key} is a switch: True or False, not {value!r}")
            if value:
                args.append("--" + name)
            continue
        if name == "seeds" and not isinstance(value, (str, numbers.Integral)):
            seeds = list(value)
            if not seeds:
                raise ValueError(f"{function}(): seeds: no seeds given")
            if not all(isinstance(s, numbers.Integral) and not isinstance(s, bool) for s in seeds):
                raise TypeError(f"{function}(): seeds: whole numbers, or the command line's text ('1-16'), not {value!r}")
            value = ",".join(str(int(s)) for s in seeds)
        if name == "image" and not isinstance(value, (str, os.PathLike)):
            for path in value:
                args += ["--image", os.fspath(path)]
            continue
        if isinstance(value, os.PathLike):
            value = os.fspath(value)
        args += ["--" + name, _text(value)]
    return args


def _numpy_or_list(values):
    try:
        import numpy
    except ImportError:
        return values
    return numpy.asarray(values, dtype=float)


class RuttingRun:
    """The result of vrut.rutting(): one specimen's, or an ensemble's.

    rut_depth_mm, dynamic_stability (passes/mm) and dynamic_stability_standard
    (the standard's value, or None past its cap) are the run's numbers; for an
    ensemble, the mean rut depth and the DS of the mean curve, as summary.json
    gives them. summary is summary.json as a dict; minutes, deformation_mm
    (the mean curve), curves_mm (one row per specimen) and the 95 % band are
    numpy arrays where numpy is installed.
    """

    def __init__(self, raw):
        self.summary = json.loads(raw["summary"])
        self.seeds = list(raw["seeds"])
        self.interrupted = bool(raw["interrupted"])
        self._raw = raw
        s = self.summary
        ensemble = s.get("ensemble")
        if ensemble is not None:
            self.rut_depth_mm = ensemble["rut_depth_mm"]["mean"]
            self.dynamic_stability = ensemble["dynamic_stability_of_mean_curve"]
            standard = ensemble.get("dynamic_stability_standard_of_mean_curve")
        else:
            self.rut_depth_mm = s["rut_depth_mm"]
            self.dynamic_stability = s["dynamic_stability_passes_per_mm"]
            standard = s.get("dynamic_stability_standard")
        self.dynamic_stability_standard = (None if standard is None or standard.get("censored")
                                           else standard["passes_per_mm"])
        self.wall_seconds = s["wall_seconds"]

    @property
    def minutes(self):
        return _numpy_or_list(self._raw["minutes"])

    @property
    def deformation_mm(self):
        return _numpy_or_list(self._raw["mean_curve_mm"])

    @property
    def curves_mm(self):
        return _numpy_or_list(self._raw["curves_mm"])

    @property
    def ci95_mm(self):
        """The 95 % interval of the mean curve at each sample (low, high); empty for one specimen."""
        return _numpy_or_list(self._raw["ci95_low_mm"]), _numpy_or_list(self._raw["ci95_high_mm"])

    @property
    def per_seed(self):
        """Each specimen's numbers (summary.json's ensemble.per_seed), or the one specimen's."""
        ensemble = self.summary.get("ensemble")
        if ensemble is not None:
            return ensemble["per_seed"]
        return [{"seed": self.seeds[0], "rut_depth_mm": self.rut_depth_mm,
                 "dynamic_stability_passes_per_mm": self.dynamic_stability}]

    def __repr__(self):
        n = len(self.seeds)
        what = f"{n} specimens" if n > 1 else f"seed {self.seeds[0]}"
        return f"<vrut.RuttingRun {what}: rut depth {self.rut_depth_mm:.2f} mm, DS {self.dynamic_stability:.0f} passes/mm>"


def _progress_bar(progress):
    """progress=True: a tqdm bar where tqdm is installed (else the command line's bar on stderr)."""
    if progress is True:
        try:
            from tqdm import tqdm
        except ImportError:
            return None, None
        bar = tqdm(total=1000, unit="permille", desc="loading")

        def update(fraction):
            bar.update(int(1000 * fraction) - bar.n)
        return update, bar
    if callable(progress):
        return progress, None
    return None, None


def _with_gradation_and_materials(options, folder, materials=None, out=None):
    """The options with a Materials' merged in and a Gradation as its text: a
    table is a CSV file in folder, or beside out (DIR.gradation-NAME.csv),
    where it lasts as long as the results, so the run can be resumed."""
    if materials is not None:
        if not isinstance(materials, Materials):
            raise TypeError(f"materials: a vrut.Materials, not {type(materials).__name__}")
        options = {**materials.options, **options}
    g = options.get("gradation")
    if isinstance(g, Gradation):
        if out is None:
            path = os.path.join(folder, g.name + ".csv")
        else:
            path = os.fspath(out).rstrip("/" + os.sep) + f".gradation-{g.name}.csv"
        options = {**options, "gradation": g._option(path)}
    return options


def rutting(out=None, progress=None, print=False, materials=None, **options):
    """Runs the virtual wheel-tracking test, as vrut-rutting does.

    out: an output folder (vrut-rutting's files), or None for none.
    progress: a callable taking the loading's fraction done (0 to 1) at each
      sample, or True for a tqdm bar where tqdm is installed.
    print: print the command line's result lines on stdout.
    materials: a vrut.Materials (its options; those given here win).
    options: vrut-rutting's options (vrut.options()), e.g. gradation=2 (or
      a vrut.Gradation), seed=1 or seeds="1-16" (or a list), width_mm=100, dim=3.

    Ctrl-C stops the run at its next sample, as on the command line (one
    that comes while the specimen is made, at the loading's first sample);
    with out= the partial results and a checkpoint are written there (go on
    with vrut-rutting --resume), then KeyboardInterrupt is raised, with the
    partial results as its .run. SIGTERM likewise raises SystemExit(143).
    """
    callback, bar = _progress_bar(progress)
    try:
        with tempfile.TemporaryDirectory(prefix="vrut-") as folder:
            args = _arguments("rutting", _with_gradation_and_materials(options, folder, materials, out))
            raw = _vrut.rutting(args, "" if out is None else str(out), callback, bool(print))
    finally:
        if bar is not None:
            bar.close()
    run = RuttingRun(raw)
    if run.interrupted:
        # As the command line: the partial results (also on the exception,
        # as .run), then Ctrl-C's KeyboardInterrupt, or SIGTERM's exit code.
        where = f"; partial results in {out}, go on with: vrut-rutting --resume {out}" if out else ""
        text = f"the run stopped at {run.summary['minutes_done']:.1f} minutes{where}"
        stop = SystemExit(raw["exit_code"]) if raw["exit_code"] == 128 + signal.SIGTERM else KeyboardInterrupt(text)
        stop.run = run
        if isinstance(stop, SystemExit):
            sys.stderr.write("vrut: terminated (SIGTERM): " + text + "\n")
        raise stop
    return run


class Specimen:
    """A specimen of vrut.specimen(): particles and measures.

    x_mm, y_mm (and z_mm in 3D) are the particles' centres, stone the stone
    (or aggregate) each belongs to, -1 for mastic; radius_mm their radius;
    summary the specimen's measures as summary.json's "specimen" gives them.
    """

    def __init__(self, raw):
        self.summary = json.loads(raw["summary"])
        self.radius_mm = raw["radius_mm"]
        self.x_mm = _numpy_or_list(raw["x_mm"])
        self.y_mm = _numpy_or_list(raw["y_mm"])
        self.z_mm = _numpy_or_list(raw["z_mm"]) if "z_mm" in raw else None
        try:
            import numpy
            self.stone = numpy.asarray(raw["stone"], dtype=int)
        except ImportError:
            self.stone = list(raw["stone"])

    def __len__(self):
        return len(self.x_mm)

    def __repr__(self):
        dim = 3 if self.z_mm is not None else 2
        return f"<vrut.Specimen {dim}D: {len(self)} particles of radius {self.radius_mm} mm>"


def specimen(**options):
    """One specimen, 2D or 3D (dim=3), or from an image (image="core.png"),
    from vrut-rutting's specimen options (gradation, seed, width_mm, ...)."""
    with tempfile.TemporaryDirectory(prefix="vrut-") as folder:
        return Specimen(_vrut.specimen(_arguments("specimen", _with_gradation_and_materials(options, folder))))


class CreepRun:
    """The result of vrut.creep(): summary is creep.json as a dict (the
    apparent Burger's parameters and their ratios to the macro ones among
    them); time_s, reduced_time_s, strain, strain_analytic (the macro
    Burger's model) and plate_stress_mpa are the samples, numpy arrays where
    numpy is installed."""

    def __init__(self, raw):
        self.summary = json.loads(raw["summary"])
        for key in ("time_s", "reduced_time_s", "strain", "strain_analytic", "plate_stress_mpa"):
            setattr(self, key, _numpy_or_list(raw[key]))

    def __repr__(self):
        r = self.summary["ratio_apparent_to_macro"]
        return f"<vrut.CreepRun apparent/macro E1 {r['E1']:.4f} eta1 {r['eta1']:.4f} E2 {r['E2']:.4f} eta2 {r['eta2']:.4f}>"


def creep(out=None, **options):
    """The virtual creep test of vrut-creep's options (vrut.options("creep")):
    a bonded all-mastic block under a constant stress, against the macro
    Burger's model. out: vrut-creep's files (creep.csv, creep.json,
    creep.png) in this folder, or None for none."""
    return CreepRun(_vrut.creep(_arguments("creep", options), "" if out is None else str(out)))
