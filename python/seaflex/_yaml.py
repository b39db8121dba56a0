"""Python values to YAML text for seaflex's loader (Model.from_dict): dicts as block
mappings, lists of scalars (and of such lists) in flow style, other lists as block
sequences. Floats are written with repr(), which round-trips every double, so a model
read back gives the same numbers bit for bit. Strings are written plain when YAML reads
them back as the same string, else double-quoted."""
import json
import math
import numbers
import re

_PLAIN = re.compile(r"[A-Za-z_/][A-Za-z0-9_ ./()+\-]*")
_NOT_PLAIN = re.compile(r"(?i)(null|~|true|false|yes|no|on|off|y|n|[-+]?\.?(inf|nan))")


def _scalar(value, where):
    if value is None:
        return "null"
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        v = float(value)
        if math.isnan(v):
            return ".nan"
        if math.isinf(v):
            return ".inf" if v > 0 else "-.inf"
        return repr(v)
    if isinstance(value, str):
        if _PLAIN.fullmatch(value) and not _NOT_PLAIN.fullmatch(value) \
                and not value.endswith(" ") and ": " not in value and " #" not in value:
            return value
        return json.dumps(value, ensure_ascii=False)
    raise TypeError(f"{where or 'the model'}: cannot write a {type(value).__name__} "
                    f"({value!r}) into a model; use dicts, lists, str, numbers, bool or None")


def _normalize(value):
    """numpy arrays and scalars to Python values, tuples to lists (recursively)."""
    if hasattr(value, "tolist") and not isinstance(value, (str, bytes)):
        value = value.tolist()
    if isinstance(value, dict):
        return {k: _normalize(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_normalize(v) for v in value]
    return value


def _flat(value):
    """True for a list of scalars, or of such lists (a table): written in flow style."""
    return all(not isinstance(v, (dict, list)) or (isinstance(v, list) and _flat(v))
               for v in value)


def _flow(value, where):
    if isinstance(value, list):
        return "[" + ", ".join(_flow(v, f"{where}.{k}") for k, v in enumerate(value)) + "]"
    return _scalar(value, where)


def _key(key, where):
    if not isinstance(key, str):
        raise TypeError(f"{where or 'the model'}: keys must be strings, got {key!r}")
    return _scalar(key, where)


def _nested(item):
    """A value written on the lines below its key or dash."""
    return (isinstance(item, dict) and item) or (isinstance(item, list) and item
                                                 and not _flat(item))


def _emit(value, indent, where, lines):
    pad = " " * indent
    if isinstance(value, dict):
        for key, item in value.items():
            path = f"{where}.{key}" if where else str(key)
            head = f"{pad}{_key(key, path)}:"
            if _nested(item):
                lines.append(head)
                _emit(item, indent + 2, path, lines)
            elif isinstance(item, dict):
                lines.append(f"{head} {{}}")
            else:
                lines.append(f"{head} {_flow(item, path)}")
        return
    for k, item in enumerate(value):  # a list
        path = f"{where}.{k}"
        if _nested(item):
            sub = []
            _emit(item, indent + 2, path, sub)
            sub[0] = f"{pad}- {sub[0][indent + 2:]}"
            lines.extend(sub)
        elif isinstance(item, dict):
            lines.append(f"{pad}- {{}}")
        else:
            lines.append(f"{pad}- {_flow(item, path)}")


def dump(value):
    """The YAML text of a model dict."""
    if not isinstance(value, dict):
        raise TypeError(f"a model is a dict of sections, got {type(value).__name__}")
    lines = []
    _emit(_normalize(value), 0, "", lines)
    return "\n".join(lines) + "\n"
