"""seaflex: flexible multibody dynamics of offshore structures, from Python.

    import seaflex
    model = seaflex.Model.from_file("examples/riser_in_current.yaml")
    model.set("environment.current.speed", 1.5)
    results = model.run(duration=10.0)
    results["riser.n10.x"]          # numpy array, one value per output row
    results.to_pandas()             # pandas.DataFrame indexed by time

The model is read and validated by the same loader as the command line and run by the
same analyses (src/seaflex/analysis/), so the results equal `seaflex run`'s files bit for
bit. Reference: docs/python.md. `import seaflex` stays cheap: numpy is imported with the
first results, pandas only by to_pandas().
"""
import os
import warnings

try:
    from . import _core
except ImportError as _error:  # a build without the extension (sanitizers): batches only
    _core = None
    _core_error = _error

__all__ = ["Model", "Results", "BeamResults", "Error", "InputError", "ModelError",
           "SolverError", "OutputError", "Interrupted", "StabilityWarning", "set_threads",
           "threads"]


def set_threads(n):
    """Threads of the element loops (the command line's --threads; default OMP_NUM_THREADS,
    else 1): 1 to the machine's hardware threads. Results are identical for any count.
    ValueError while an analysis runs in another thread."""
    _need_core().set_threads(int(n))


def threads():
    """The threads of the element loops."""
    return _need_core().threads()


class Error(Exception):
    """Any error seaflex reports; str(e) is the message the command line prints."""


class InputError(Error, ValueError):
    """A model that cannot be accepted (the command line's exit code 2): the message lists
    every problem as file:line:col: key: message."""


class ModelError(InputError):
    """A well-formed but inconsistent model (the command line prints "seaflex: model error:
    " before the message; exit code 2)."""


class SolverError(Error, RuntimeError):
    """A computation that could not go on (the command line prints "seaflex: solver
    failure: " before the message; exit code 3). `results` holds what was computed up to
    the failure (a run's rows, or statics' last converged increment), or None."""

    results = None


class OutputError(Error, OSError):
    """A result file that could not be written (the command line's exit code 3)."""

    results = None


class Interrupted(KeyboardInterrupt):
    """A run stopped by Ctrl-C (KeyboardInterrupt) after its current step; `results` holds
    the rows computed up to it."""

    results = None


class StabilityWarning(UserWarning):
    """Statics found an equilibrium that is not stable (a folded line, a column in
    compression far beyond its buckling load), or modes found omega^2 < 0; the results
    are returned all the same (docs/model-format.md section 12, "Unstable equilibria").
    warnings.simplefilter("error", seaflex.StabilityWarning) makes it an exception."""


def _warn_analysis(found, results=None, stacklevel=3):
    """Keeps an analysis's warnings in results.warnings and issues them as
    StabilityWarning (before an error of the same call is raised: the warning may explain
    it; with warnings.simplefilter("error", StabilityWarning) the raised warning carries
    the results as its .results)."""
    found = list(found)
    if results is not None:
        results.warnings = found
    for w in found:
        warning = StabilityWarning(w)
        warning.results = results
        warnings.warn(warning, stacklevel=stacklevel)


_ERRORS = {"input": InputError, "model": ModelError, "solver": SolverError,
           "output": OutputError, "error": InputError, "usage": RuntimeError}


def _need_core():
    if _core is None:
        raise ImportError("seaflex._core is not built (a sanitizer or fuzz build?): "
                          f"{_core_error}")
    return _core


def _raise(kind, message, results=None, exception=None):
    """Raises the error a _core call reported; a Python exception raised during the call
    (KeyboardInterrupt or one from the progress callback) wins, with the results attached."""
    if exception is not None:
        if isinstance(exception, KeyboardInterrupt) and not isinstance(exception, Interrupted):
            stopped = Interrupted(message or "interrupted")
            stopped.results = results
            raise stopped from None
        try:
            exception.results = results
        except AttributeError:
            pass
        raise exception
    if kind == "interrupted":
        stopped = Interrupted(message)
        stopped.results = results
        raise stopped
    if kind:
        error = _ERRORS.get(kind, Error)(message)
        if kind != "usage":
            error.results = results
        raise error from None


class Model:
    """A validated seaflex model (docs/model-format.md) with its YAML text.

    Build one with Model.from_file, Model.from_yaml or Model.from_dict; the constructor is
    internal. Every way validates with the command line's loader and raises InputError
    with its exact message.
    """

    def __init__(self, core, text, name, source_path):
        self._core = core
        self._text = text
        self._name = name
        #: the file the model was read from (absolute), or None; relative file references
        #: in the model (WAMIT files, RAO tables) resolve against its directory
        self.source_path = source_path
        if core.warnings:
            for w in core.warnings:
                warnings.warn(w, stacklevel=3)

    # --- building ---------------------------------------------------------------------
    @classmethod
    def _load(cls, text, name, source_path):
        core, kind, message = _need_core().load(text, name)
        _raise(kind, message)
        return cls(core, text, name, source_path)

    @classmethod
    def from_file(cls, path):
        """Reads a model file; messages name the file as given (as `seaflex check PATH`)."""
        path = os.fspath(path)
        text, kind, message = _need_core().read_model_file(path)
        _raise(kind, message)
        return cls._load(text, path, os.path.abspath(path))

    @classmethod
    def from_yaml(cls, text, source_path=None):
        """A model from YAML text. Messages name it "<yaml>" (or source_path); relative file
        references resolve against source_path's directory, else the working directory."""
        source_path = os.path.abspath(os.fspath(source_path)) if source_path else None
        return cls._load(text, source_path or "<yaml>", source_path)

    @classmethod
    def from_dict(cls, d, source_path=None):
        """A model from a dict (as to_dict() gives): written as YAML text (the `yaml`
        property) and read by the same loader, so messages give file:line:col in that text,
        named "<dict>" (or "<source_path> (edited)"; relative file references resolve
        against source_path's directory)."""
        from . import _yaml
        text = _yaml.dump(d)
        source_path = os.path.abspath(os.fspath(source_path)) if source_path else None
        name = f"{source_path} (edited)" if source_path else "<dict>"
        return cls._load(text, name, source_path)

    # --- inspecting and changing --------------------------------------------------------
    @property
    def yaml(self):
        """The YAML text the model was read from (generated for from_dict and set())."""
        return self._text

    @property
    def name(self):
        """The name messages give the model (the file as given, "<yaml>", "<dict>")."""
        return self._name

    @property
    def channels(self):
        """Names of the channels a run records (those the output section selects)."""
        return list(self._core.channels)

    @property
    def warnings(self):
        """The loader's warnings (also issued as Python warnings when loaded)."""
        return list(self._core.warnings)

    def to_dict(self):
        """The model as a fresh dict of dicts, lists and scalars, in file order (YAML 1.2
        core schema: null, bool, int, float; quoted values stay str)."""
        return _need_core().yaml_to_python(self._text, self._name)

    def copy(self):
        """An independent model with the same text (read again: it can run in another
        thread while this one runs)."""
        return Model._load(self._text, self._name, self.source_path)

    def set(self, path, value, create=False):
        """Sets one value by its key path ("environment.current.speed"; list items by index,
        "connections.0.stiffness"; a list of keys for names holding dots) and reloads the
        model; returns self. A key that
        does not exist raises InputError with a did-you-mean (create=True adds a missing
        last key). An invalid value raises InputError and leaves the model unchanged."""
        d = self.to_dict()
        keys = path.split(".") if isinstance(path, str) else list(path)
        node = d
        for i, key in enumerate(keys):
            last = i == len(keys) - 1
            where = ".".join(str(k) for k in keys[:i + 1])
            if isinstance(node, list):
                try:
                    index = int(key)
                    node[index]
                except (ValueError, IndexError):
                    raise InputError(f"{where}: no item {key} in a list of {len(node)} "
                                     f"(indices 0 to {len(node) - 1})") from None
                if last:
                    node[index] = value
                else:
                    node = node[index]
                continue
            if not isinstance(node, dict):
                raise InputError(f"{where}: {'.'.join(keys[:i])} is a value "
                                 f"({node!r}), not a section with keys")
            if key not in node:
                if last and create:
                    node[key] = value
                    break
                hint = _core.suggestion(key, [str(k) for k in node])
                raise InputError(f"{where}: no such key in the model; {hint}")
            if last:
                node[key] = value
            else:
                node = node[key]
        new = Model.from_dict(d, self.source_path)
        self._core, self._text, self._name = new._core, new._text, new._name
        return self

    def check(self):
        """The summary `seaflex check` prints (the model is validated when built)."""
        return self._core.summary() + "model OK\n"

    # --- analyses -----------------------------------------------------------------------
    def statics(self, output_dir=None, progress=None, beams=True):
        """Static equilibrium: Results with one row (the statics.csv of `seaflex statics`,
        also written to output_dir when given). progress(load_factor, 1.0) after each load
        increment. SolverError carries the last converged increment as its results.
        beams=False keeps the channels only (see run())."""
        out = None if output_dir is None else os.fspath(output_dir)
        recorded, kind, message, exception, found = _need_core().statics(
            self._core, out, progress, bool(beams))
        results = Results(recorded, self._core)
        _warn_analysis(found, results)
        _raise(kind, message, results, exception)
        return results

    def run(self, duration=None, progress=None, output_dir=None, beams=True):
        """A dynamic run as `seaflex run` performs it (statics first when the model starts
        from them): Results of every output row. duration (s) overrides
        dynamics.duration (validated as in the file). progress(t, duration) is called at
        every output row (and with t = 0 after each statics load increment); the GIL is
        released in between. Ctrl-C stops the run after its
        current step and raises seaflex.Interrupted (a KeyboardInterrupt) whose results
        hold the rows so far; a solver failure raises SolverError with them. output_dir:
        also write the command line's result files there. beams: keep the beam results
        along the length of every row in memory (rows x stations x 16 doubles per beam) when
        the output section writes them (beam_results: all, the default); False: the
        channels only."""
        model = self
        if duration is not None and self._core.has_dynamics:
            d = self.to_dict()
            d["dynamics"]["duration"] = float(duration)
            model = Model.from_dict(d, self.source_path)
        out = None if output_dir is None else os.fspath(output_dir)
        statics, recorded, report, kind, message, exception, found = _need_core().run(
            model._core, out, progress, bool(beams))
        results = Results(recorded, model._core, report)
        if statics is not None:
            results.statics = Results(statics, model._core)
        _warn_analysis(found, results)
        _raise(kind, message, results, exception)
        return results

    def modes(self, n=10, about_initial=False):
        """The lowest n natural modes about static equilibrium (or the initial state), as
        `seaflex modes` computes them: a dict of numpy arrays frequency_hz, period_s,
        omega_rad_s, energy_share, the list dominant_coordinate, shapes (coordinates x n,
        mass-normalized) and the coordinate names."""
        result, kind, message, exception, found = _need_core().modes(self._core, int(n),
                                                                     bool(about_initial))
        _warn_analysis(found)
        _raise(kind, message, None, exception)
        return result

    def __reduce__(self):  # pickling (multiprocessing, Dask): the text, read again
        return (Model._load, (self._text, self._name, self.source_path))

    def __repr__(self):
        return f"<seaflex.Model {self._name}>"


class Results:
    """Recorded channels of an analysis. results["name"] is a read-only numpy array (a view
    of the recorded values, no copy), results.time the output times; the channel names
    are those of the CSV header and the HDF5 channel_names. results.report: steps, rows,
    end_time, ... of a run (None for statics); results.statics: the statics row a run
    started from (or None)."""

    def __init__(self, recorded, core, report=None):
        self._recorded = recorded
        self._core = core  # the model the beams belong to
        self._index = {name: k for k, name in enumerate(recorded.channels)}
        self.report = report
        self.statics = None
        self.warnings = []  # the analysis's StabilityWarning texts (statics, run)

    @property
    def time(self):
        return self._recorded.time

    @property
    def channels(self):
        """Channel names, in the files' column order."""
        return list(self._recorded.channels)

    def keys(self):
        return self.channels

    def __len__(self):
        return self._recorded.rows

    def __contains__(self, name):
        return name in self._index or name == "time"

    def __getitem__(self, name):
        if name == "time":
            return self.time
        try:
            return self._recorded.column(self._index[name])
        except KeyError:
            hint = _core.suggestion(name, self.channels)
            raise KeyError(f"no channel '{name}'; {hint}") from None

    @property
    def beams(self):
        """Names of the beams with results along the length (output.beam_results: all)."""
        return list(self._recorded.beam_names)

    def beam(self, name):
        """Results along the length of one beam (BeamResults)."""
        names = self.beams
        if name not in names:
            hint = _core.suggestion(name, names) if names else \
                "no beam results were recorded (output.beam_results: all keeps them)"
            raise KeyError(f"no beam results for '{name}'; {hint}")
        return BeamResults(self, names.index(name), name)

    def to_pandas(self):
        """A pandas.DataFrame of the channels, indexed by time (a copy)."""
        import pandas
        frame = pandas.DataFrame({name: self[name] for name in self.channels},
                                 index=pandas.Index(self.time, name="time"))
        return frame

    def statistics(self, start=0.0, channels=None):
        """Statistics of each channel over the rows from `start` (s) on, as the model's
        statistics section gives them in statistics.csv (post/statistics.hpp): a
        pandas.DataFrame indexed by channel with the columns count, duration, min, max,
        mean, std, skewness, kurtosis, up_crossings, period, peaks."""
        import math
        import pandas
        dt = self._core.output_interval
        first = 0
        if start > 0 and dt > 0:  # the first output row at or after start
            first_time = math.ceil(start / dt - 1e-9) * dt
            times = self.time
            while first < len(times) and times[first] < first_time - 1e-6 * dt:
                first += 1
        names = self.channels if channels is None else list(channels)
        rows = {name: _core.record_statistics(self.time, self[name], first) for name in names}
        frame = pandas.DataFrame.from_dict(rows, orient="index")
        frame.index.name = "channel"
        return frame

    def __repr__(self):
        return f"<seaflex.Results {len(self)} rows x {len(self._index)} channels>"


class BeamResults:
    """One beam's results along the length (docs/results-format.md): s, xi, element and
    node of every station; beam["tension_effective"] a (rows, stations) read-only view."""

    def __init__(self, results, index, name):
        self._results = results
        self._index = index
        self.name = name
        stations = results._recorded.beam_stations(index)
        self.s = stations["s"]
        self.xi = stations["xi"]
        self.element = stations["element"]
        self.node = stations["node"]

    @property
    def quantities(self):
        return list(_core.Recorded.beam_quantities)

    @property
    def time(self):
        return self._results.time

    def __getitem__(self, quantity):
        names = self.quantities
        if quantity not in names:
            raise KeyError(f"no beam quantity '{quantity}'; "
                           f"{_core.suggestion(quantity, names)}")
        return self._results._recorded.beam_values(self._index, names.index(quantity))

    def __repr__(self):
        return f"<seaflex.BeamResults {self.name}: {len(self.s)} stations>"
