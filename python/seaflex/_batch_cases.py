"""The load cases of a seaflex batch: the CASES.yaml format, its checks and the case models.

A batch is a base model plus variations: key paths into the model (`environment.waves.height`,
`bodies.riser.density`, `joints.shoulder.stiffness` or `joints.0.stiffness`) with their values,
as a product of lists and/or an explicit table (docs/python-batch.md). Every message names the
file, line, column and key (`cases.yaml:4:3: product.environment.waves.heigth: ...`), like the
command line's. Models are read and written with the YAML 1.2 core schema that yaml-cpp (the
model loader) uses: `1e3` is a number, `no`/`off` and dates stay text.
"""

import copy
import difflib
import hashlib
import itertools
import math
import os
import re
import shutil
import subprocess
import tempfile
from dataclasses import dataclass, field

import yaml


class BatchError(Exception):
    """Bad input of a batch (the cases, the base model, an option, the output folder, the
    scheduler). The message names the file, line, column and key; `seaflex batch` prints it
    and exits with code 2."""


# the most cases one batch may hold: a product of a few long lists grows fast
MAX_CASES = 100000

TOP_KEYS = ["model", "command", "set", "product", "table", "summary", "timeout"]
SUMMARY_KEYS = ["channels", "statistics", "start"]
# statistics of a channel computed from the HDF5 results over the rows with t >= start
BASIC_STATISTICS = ["min", "max", "mean", "std"]
# from statistics.csv / extremes.csv (a model with a statistics section, docs/results-format.md)
SECTION_STATISTICS = ["count", "duration", "skewness", "kurtosis", "up_crossings", "period",
                      "peaks", "mpm_rayleigh", "mpm_weibull", "mpm_gumbel"]
COMMANDS = ["run", "statics"]
NAME_PATTERN = re.compile(r"^[A-Za-z0-9][A-Za-z0-9._+=-]{0,119}$")


# YAML 1.2 core schema (yaml-cpp): PyYAML's YAML 1.1 rules would turn `off` into False, `1e3`
# into text and `010` into 8
class Loader(yaml.SafeLoader):
    pass


class Dumper(yaml.SafeDumper):
    pass


_RESOLVERS = [
    ("tag:yaml.org,2002:null", r"^(?:~|null|Null|NULL|)$", ["~", "n", "N", ""]),
    ("tag:yaml.org,2002:bool", r"^(?:true|True|TRUE|false|False|FALSE)$", list("tTfF")),
    ("tag:yaml.org,2002:int", r"^[-+]?[0-9]+$", list("-+0123456789")),
    ("tag:yaml.org,2002:float",
     r"^(?:[-+]?(?:\.[0-9]+|[0-9]+(?:\.[0-9]*)?)(?:[eE][-+]?[0-9]+)?"
     r"|[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN))$", list("-+0123456789.")),
    ("tag:yaml.org,2002:merge", r"^(?:<<)$", ["<"]),
]
for _cls in (Loader, Dumper):
    _cls.yaml_implicit_resolvers = {}
    for _tag, _regexp, _first in _RESOLVERS:
        _cls.add_implicit_resolver(_tag, re.compile(_regexp), _first)


def _construct_float(loader, node):
    text = loader.construct_scalar(node).lower()
    if text.endswith("inf"):
        return -math.inf if text.startswith("-") else math.inf
    if text == ".nan":
        return math.nan
    return float(text)


Loader.add_constructor("tag:yaml.org,2002:int", lambda l, n: int(l.construct_scalar(n), 10))
Loader.add_constructor("tag:yaml.org,2002:float", _construct_float)


def dump_model(model):
    """The YAML text of a model (block style, short lists inline, keys in their order)."""
    return yaml.dump(model, Dumper=Dumper, sort_keys=False, allow_unicode=True,
                     default_flow_style=None, width=1 << 30)


def value_text(value):
    """A value as the summary and the case header show it (YAML flow style)."""
    if isinstance(value, str):
        return value
    return yaml.dump(value, Dumper=Dumper, default_flow_style=True, width=1 << 30).strip() \
        .removesuffix("...").strip()


class Marks:
    """Where the keys of a YAML file are (line:col), for messages; `source` is the file name,
    or a label ("cases") for data given in Python."""

    def __init__(self, source, node=None):
        self.source = source
        self.node = node

    def where(self, *keys):
        node = self.node
        mark = node.start_mark if node is not None else None
        for key in keys:
            found = None
            if isinstance(node, yaml.MappingNode):
                for k, v in node.value:
                    if isinstance(k, yaml.ScalarNode) and k.value == key:
                        found, mark = v, k.start_mark
                        break
            elif isinstance(node, yaml.SequenceNode) and isinstance(key, int):
                if key < len(node.value):
                    found = node.value[key]
                    mark = found.start_mark
            if found is None:
                break
            node = found
        if self.node is None or mark is None:
            return self.source
        return f"{self.source}:{mark.line + 1}:{mark.column + 1}"

    def error(self, keys, key_text, message):
        key = f" {key_text}:" if key_text else ""
        return BatchError(f"{self.where(*keys)}:{key} {message}")


def read_yaml(path, what):
    """(data, Marks) of a YAML file; BatchError when it cannot be read or parsed."""
    try:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    except (OSError, UnicodeDecodeError) as e:
        raise BatchError(f"{path}: cannot read the {what}: {getattr(e, 'strerror', None) or e}")
    try:
        node = yaml.compose(text, Loader=Loader)
        data = yaml.load(text, Loader=Loader)
    except yaml.YAMLError as e:
        mark = getattr(e, "problem_mark", None)
        where = f"{path}:{mark.line + 1}:{mark.column + 1}" if mark else path
        raise BatchError(f"{where}: YAML syntax error: {getattr(e, 'problem', None) or e}")
    return data, Marks(path, node)


def did_you_mean(word, choices):
    close = difflib.get_close_matches(str(word), [str(c) for c in choices], n=1, cutoff=0.6)
    if close:
        return f"; did you mean '{close[0]}'?"
    if choices:
        return "; expected one of " + ", ".join(f"'{c}'" for c in choices)
    return ""


@dataclass
class Summary:
    channels: list = None  # shell patterns; None: every channel of the results
    statistics: list = field(default_factory=lambda: list(BASIC_STATISTICS))
    start: float = None  # s; None: the model's statistics.start, else 0


@dataclass
class Case:
    name: str
    values: dict  # key path -> value
    digest: str = ""  # sha256 of what makes the case's model (Batch.digest)


@dataclass
class Batch:
    """The cases of a batch. A case's model is made when it is submitted (model(), text()):
    a batch of many cases does not hold all their models at once."""
    base: dict
    base_path: str  # the base model's file, or None
    cases: list
    paths: list  # the varied key paths, in order
    summary: Summary
    command: str = "run"
    timeout: float = None
    source: str = "cases"
    fixed: dict = field(default_factory=dict)  # `set`
    base_digest: str = ""

    @property
    def base_dir(self):
        return os.path.dirname(os.path.abspath(self.base_path)) if self.base_path else None

    def model(self, case):
        """The case's model: the base model, `set`, the case's values, absolute file names."""
        model = copy.deepcopy(self.base)
        for path, value in itertools.chain(self.fixed.items(), case.values.items()):
            set_value(model, path, value)
        if self.base_dir:
            absolute_files(model, self.base_dir)
        return model

    def text(self, case, model=None):
        """The case's model file: a comment naming the case and its values, then the model."""
        header = f"# seaflex batch case {case.name}" + "".join(
            f"\n#   {p} = {value_text(v)}" for p, v in case.values.items()) + "\n"
        return header + dump_model(self.model(case) if model is None else model)

    def start(self, model):
        """s: the summary's statistics leave out the rows before (summary.start, else the
        model's statistics.start, else 0)."""
        if self.summary.start is not None:
            return self.summary.start
        section = model.get("statistics")
        start = section.get("start", 0.0) if isinstance(section, dict) else 0.0
        return float(start) if isinstance(start, (int, float)) else 0.0

    def digest(self, name, values):
        """SHA-256 of everything the case's model and run are made of: the command, the base
        model (as written, file names absolute), its folder, `set`, the name and the values
        (Python's repr: exact for numbers, in their order)."""
        key = "\n".join([self.command, self.base_digest, str(self.base_dir),
                         repr(list(self.fixed.items())), name, repr(list(values.items()))])
        return hashlib.sha256(key.encode()).hexdigest()


def _split(path):
    return path.split(".")


def _resolve(model, path):
    """Walks a key path: (True, loader_key) when it exists, else (False, details) where details
    = (loader key of the part that exists, missing component, keys there, kind, is_last)."""
    node, loader_key = model, ""
    comps = _split(path)
    for i, comp in enumerate(comps):
        last = i == len(comps) - 1
        if isinstance(node, dict):
            if comp in node:
                node = node[comp]
                loader_key = f"{loader_key}.{comp}" if loader_key else comp
                continue
            return False, (loader_key, comp, list(node.keys()), "key", last)
        if isinstance(node, list):
            names = [e.get("name") if isinstance(e, dict) else None for e in node]
            if comp.isdigit() and int(comp) < len(node):
                index = int(comp)
            elif comp in names:
                index = names.index(comp)
            else:
                shown = [n for n in names if n is not None] or list(range(len(node)))
                return False, (loader_key, comp, shown, "element", last)
            node = node[index]
            loader_key = f"{loader_key}[{index}]"
            continue
        shown = f"'{node}'" if isinstance(node, str) else value_text(node)
        return False, (loader_key, comp, [], f"the value {shown}", last)
    return True, loader_key


def set_value(model, path, value):
    """Sets a key path in a model (dicts made where keys are missing)."""
    comps = _split(path)
    node = model
    for i, comp in enumerate(comps):
        last = i == len(comps) - 1
        if isinstance(node, list):
            names = [e.get("name") if isinstance(e, dict) else None for e in node]
            index = int(comp) if comp.isdigit() and int(comp) < len(node) else names.index(comp)
            if last:
                node[index] = copy.deepcopy(value)
            else:
                node = node[index]
        elif last:
            node[comp] = copy.deepcopy(value)
        else:
            if not isinstance(node.get(comp), (dict, list)):
                node[comp] = {}
            node = node[comp]


def absolute_files(model, base_dir):
    """Makes the model's file references (keys `file` and `wamit`) absolute, relative to
    base_dir as the loader reads them, so that a case model written elsewhere finds them."""
    if isinstance(model, dict):
        for k, v in model.items():
            if k in ("file", "wamit") and isinstance(v, str) and v and not os.path.isabs(v):
                model[k] = os.path.normpath(os.path.join(base_dir, v))
            else:
                absolute_files(v, base_dir)
    elif isinstance(model, list):
        for v in model:
            absolute_files(v, base_dir)


def find_executable(executable=None):
    """The seaflex executable: the argument, else $SEAFLEX_EXECUTABLE, else seaflex on PATH."""
    for candidate in (executable, os.environ.get("SEAFLEX_EXECUTABLE")):
        if candidate:
            return candidate
    return shutil.which("seaflex")


_UNKNOWN_KEY = re.compile(r"^.*?:\d+:\d+: (?P<key>\S+): unknown key(?P<rest>.*)$")


def _loader_verdict(base, base_dir, path, value, executable):
    """Asks the model loader (seaflex check) about a key path that the base model does not
    hold: (loader key, rest of its message) when it names an unknown key on the path, None
    when the key is known, "unavailable" without an executable."""
    if not executable:
        return "unavailable"
    model = copy.deepcopy(base)
    set_value(model, path, value)
    if base_dir:
        absolute_files(model, base_dir)
    with tempfile.TemporaryDirectory(prefix="seaflex-batch-check-") as tmp:
        file = os.path.join(tmp, "model.yaml")
        with open(file, "w", encoding="utf-8") as f:
            f.write(dump_model(model))
        try:
            proc = subprocess.run([executable, "check", file], capture_output=True, text=True,
                                  timeout=120)
        except (OSError, subprocess.TimeoutExpired):
            return "unavailable"
    for line in proc.stderr.splitlines():
        m = _UNKNOWN_KEY.match(line)
        if m:
            return m.group("key"), m.group("rest")
    return None


def _label(keys):
    """The key of a message: product.environment.waves.height, table[2].bodies.riser.density."""
    text = ""
    for k in keys:
        text += f"[{k}]" if isinstance(k, int) else (f".{k}" if text else str(k))
    return text


def _check_path(base, base_dir, path, value, marks, keys, model_name, executable):
    """Refuses a key path that names no key of the model (did you mean). A last key that the
    base model leaves out is asked of the model loader (seaflex check): the format may know
    it (a default the model does not write)."""
    label = _label(keys)
    if not isinstance(path, str) or not path or any(not c for c in _split(path)):
        raise marks.error(keys, label,
                          f"expected a key path such as environment.waves.height, got '{path}'")
    found, info = _resolve(base, path)
    if found:
        return
    parent, comp, choices, kind, last = info
    inside = f"in {parent}" if parent else "at the top level"
    if kind == "element":
        raise marks.error(keys, label,
                          f"no element '{comp}' {inside} of the model {model_name} (an index "
                          f"from 0 or a name){did_you_mean(comp, choices)}")
    if kind != "key":
        raise marks.error(keys, label, f"{parent} of the model {model_name} is {kind}, not a "
                          f"section with the key '{comp}'")
    verdict = _loader_verdict(base, base_dir, path, value, executable) if last else "unknown"
    if verdict is None:
        return  # a key the model leaves out but the format knows
    rest = did_you_mean(comp, choices)
    if isinstance(verdict, tuple):
        _, rest = verdict
    raise marks.error(keys, label, f"unknown key '{comp}' {inside} of the model {model_name}"
                      f"{rest}")


def _number(data, key, marks, keys, low, high, unit):
    value = data.get(key)
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not (
            low <= value <= high) or math.isnan(value):
        raise marks.error(keys, ".".join(keys),
                          f"expected a number from {low:g} to {high:g} {unit}, got "
                          f"{value_text(value)}")
    return float(value)


def _mapping(value, marks, keys, what):
    if value is None:
        return {}
    if not isinstance(value, dict):
        raise marks.error(keys, _label(keys),
                          f"expected {what}, got {value_text(value)}")
    return value


def _summary(data, marks, has_statistics_section):
    s = _mapping(data, marks, ["summary"], "a mapping (channels, statistics, start)")
    for key in s:
        if key not in SUMMARY_KEYS:
            raise marks.error(["summary", key], f"summary.{key}",
                              f"unknown key{did_you_mean(key, SUMMARY_KEYS)}")
    summary = Summary()
    if "channels" in s:
        channels = s["channels"]
        if isinstance(channels, str):
            channels = [channels]
        if not isinstance(channels, list) or not all(isinstance(c, str) and c for c in channels):
            raise marks.error(["summary", "channels"], "summary.channels",
                              "expected a list of channel names or shell patterns "
                              f"(riser.tension_effective, platform.*), got {value_text(channels)}")
        summary.channels = channels
    if "statistics" in s:
        stats = s["statistics"]
        if isinstance(stats, str):
            stats = [stats]
        known = BASIC_STATISTICS + SECTION_STATISTICS
        if not isinstance(stats, list) or not stats:
            raise marks.error(["summary", "statistics"], "summary.statistics",
                              f"expected a list of statistics ({', '.join(known)}), got "
                              f"{value_text(stats)}")
        for i, name in enumerate(stats):
            if name not in known:
                raise marks.error(["summary", "statistics", i], "summary.statistics",
                                  f"unknown statistic '{name}'{did_you_mean(name, known)}")
            if name in SECTION_STATISTICS and not has_statistics_section:
                raise marks.error(["summary", "statistics", i], "summary.statistics",
                                  f"'{name}' comes from statistics.csv, which needs a statistics "
                                  "section in the model (docs/model-format.md); without it: "
                                  + ", ".join(BASIC_STATISTICS))
        summary.statistics = stats
    if "start" in s:
        summary.start = _number(s, "start", marks, ["summary", "start"], 0, 1e9, "s")
    return summary


def _value_label(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return format(value, ".15g")
    if isinstance(value, str):
        return value
    return None


def _labels(paths):
    """The shortest trailing part of each key path that tells it from the others."""
    labels = {}
    for path in paths:
        comps = _split(path)
        for n in range(1, len(comps) + 1):
            label = ".".join(comps[-n:])
            if all(not (".".join(_split(p)[-n:]) == label) for p in paths if p != path):
                break
        labels[path] = label
    return labels


def _names(raw, paths, marks):
    """Case names: the table's `name` (plus the product's values), else the varied values
    (height=2_direction=45), else case001, case002, ... when those are not usable names."""
    labels = _labels(paths)
    names = []
    for explicit, values in raw:
        parts = []
        for path, value in values.items():
            text = _value_label(value)
            parts.append(None if text is None else f"{labels[path]}={text}")
        generated = None if None in parts else "_".join(parts)
        if explicit is not None:
            names.append(f"{explicit}_{generated}" if values and generated else
                         explicit if not values else None)
        else:
            names.append(generated or ("base" if not values else None))
    if all(n is not None and NAME_PATTERN.match(n) for n in names) and len(set(names)) == len(
            names):
        return names
    width = len(str(len(raw)))
    return [f"case{i + 1:0{width}d}" for i in range(len(raw))]


def parse(data, marks, base=None, base_path=None, executable=None):
    """The batch described by data (the contents of CASES.yaml, or the `cases` argument of
    seaflex.batch.run): checks everything that can be checked before a case runs."""
    if isinstance(data, list):
        data = {"table": data}
    data = _mapping(data, marks, [], "a mapping (model, product, table, set, summary)")
    if data and not any(k in TOP_KEYS for k in data):
        data = {"product": data}  # a bare mapping of key paths to lists
    for key in data:
        if key not in TOP_KEYS:
            raise marks.error([key], str(key), f"unknown key{did_you_mean(key, TOP_KEYS)}")
    if base is None:
        if "model" not in data:
            raise marks.error([], "model", "the base model is missing (model: FILE)")
        model = data["model"]
        if not isinstance(model, str) or not model:
            raise marks.error(["model"], "model", f"expected a file name, got {value_text(model)}")
        cases_dir = os.path.dirname(marks.source) if marks.node is not None else ""
        base_path = os.path.normpath(os.path.join(cases_dir, model))
        if not os.path.isfile(base_path):
            raise marks.error(["model"], "model", f"{base_path}: no such model file")
        base, _ = read_yaml(base_path, "model file")
    elif "model" in data:
        raise marks.error(["model"], "model",
                          "the base model is given twice (as base_model and in the cases)")
    if not isinstance(base, dict):
        raise BatchError(f"{base_path or 'base_model'}: a model is a mapping (title, "
                         f"environment, bodies, ...), got {value_text(base)}")
    base_dir = os.path.dirname(os.path.abspath(base_path)) if base_path else None
    model_name = base_path or "base_model"
    executable = find_executable(executable)

    command = data.get("command", "run")
    if command not in COMMANDS:
        raise marks.error(["command"], "command",
                          f"expected run or statics, got {value_text(command)}"
                          f"{did_you_mean(command, COMMANDS) if isinstance(command, str) else ''}")
    timeout = None
    if "timeout" in data:
        timeout = _number(data, "timeout", marks, ["timeout"], 0.001, 1e7, "s")
    fixed = _mapping(data.get("set"), marks, ["set"], "a mapping of key paths to values")
    product = _mapping(data.get("product"), marks, ["product"],
                       "a mapping of key paths to lists of values")
    table = data.get("table") or []
    if not isinstance(table, list):
        raise marks.error(["table"], "table",
                          f"expected a list of cases (mappings of key paths to values), got "
                          f"{value_text(table)}")

    for path, value in fixed.items():
        _check_path(base, base_dir, path, value, marks, ["set", path], model_name, executable)
    count = 1
    for path, values in product.items():
        if not isinstance(values, list) or not values:
            raise marks.error(["product", path], f"product.{path}",
                              f"expected a list of values, got {value_text(values)}")
        if path in fixed:
            raise marks.error(["product", path], f"product.{path}",
                              "also given in set: a key is either fixed or varied")
        _check_path(base, base_dir, path, values[0], marks, ["product", path], model_name,
                    executable)
        count *= len(values)
    table_paths = []
    for i, row in enumerate(table):
        row = _mapping(row, marks, ["table", i], "a mapping of key paths to values")
        if "name" in row and (not isinstance(row["name"], str) or not NAME_PATTERN.match(
                row["name"])):
            raise marks.error(["table", i, "name"], f"table[{i}].name",
                              "a case name is up to 120 letters, digits and . _ + = - (not "
                              f"starting with . _ + = -), got {value_text(row['name'])}")
        for path, value in row.items():
            if path == "name":
                continue
            if path in fixed or path in product:
                raise marks.error(["table", i, path], f"table[{i}].{path}",
                                  f"also given in {'set' if path in fixed else 'product'}: a "
                                  "key is varied in one place")
            _check_path(base, base_dir, path, value, marks, ["table", i, path], model_name,
                        executable)
            if path not in table_paths:
                table_paths.append(path)
    count *= max(1, len(table))
    if count > MAX_CASES:
        raise marks.error(["product"] if product else ["table"], "product" if product else "table",
                          f"{count} cases, more than the limit of {MAX_CASES} for one batch")
    names_given = [row.get("name") for row in table if isinstance(row, dict) and "name" in row]
    if len(set(names_given)) != len(names_given):
        dup = next(n for n in names_given if names_given.count(n) > 1)
        raise marks.error(["table"], "table", f"the case name '{dup}' is given twice")

    paths = table_paths + list(product.keys())
    raw = []
    for row in table or [{}]:
        row_values = {k: v for k, v in row.items() if k != "name"}
        for combo in itertools.product(*product.values()):
            values = dict(row_values)
            values.update(zip(product.keys(), combo))
            explicit = row.get("name")
            raw.append((explicit, values if explicit is None else dict(zip(product.keys(), combo)),
                        values))
    names = _names([(e, v) for e, v, _ in raw], paths, marks)

    stats_section = "statistics" in base or "statistics" in fixed
    summary = _summary(data.get("summary"), marks, stats_section)
    batch = Batch(base, base_path, [], paths, summary, command, timeout,
                  marks.source if marks.node is not None else "cases", dict(fixed))
    written = copy.deepcopy(base)
    if batch.base_dir:
        absolute_files(written, batch.base_dir)
    batch.base_digest = hashlib.sha256(dump_model(written).encode()).hexdigest()
    for name, (_, _, values) in zip(names, raw):
        batch.cases.append(Case(name, values, batch.digest(name, values)))
    return batch

