"""Mutations of Maris scenarios for fuzz_cli.py (Python 3 standard library only).

A mutant is a Case: the text of a scenario file (or a special path such as a FIFO), optional
`--set` assignments, optional data files written beside it, and a description of what was broken
(`target`: the JSON path or file that the error message is expected to name).
"""

import json
import os
import random
from dataclasses import dataclass, field

EXTREME_NUMBERS = ["0", "-0.0", "-1", "1e-300", "5e-324", "1e-20", "1e-12", "1e-8", "1e-6", "1e300", "-1e300",
                   "1.7976931348623157e308", "9223372036854775808", "-9223372036854775809",
                   "18446744073709551616", "1e400", "-1e400", "1" + "0" * 400, "0.5", "1e6", "123456789"]
TYPE_SWAPS = ['"text"', "null", "true", "[]", "{}", "[1, 2]", '{"a": 1}', '""', '"nan"', '"inf"']
TOP_KEYS = ("format", "scene", "name", "description", "parameters")


@dataclass
class Case:
    kind: str                      # mutation operator
    target: str                    # what was broken: a JSON path, "--set", "file"
    text: bytes = b""              # scenario file content ("" with special set)
    special: str = ""              # "fifo", "dir", "loop", "missing", "devzero", "empty" instead of text
    sets: list = field(default_factory=list)
    data: dict = field(default_factory=dict)  # file name -> bytes, written beside the scenario


def leaves(value, path=""):
    """(path, value) of every leaf and container below `value`, paths as Maris prints them."""
    out = []
    if isinstance(value, dict):
        for k, v in value.items():
            p = f"{path}.{k}" if path else k
            out.append((p, v))
            out.extend(leaves(v, p))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            p = f"{path}[{i}]"
            out.append((p, v))
            out.extend(leaves(v, p))
    return out


def split_path(path):
    parts = []
    for dotted in path.split("."):
        while "[" in dotted:
            head, rest = dotted.split("[", 1)
            if head:
                parts.append(head)
            index, dotted = rest.split("]", 1)
            parts.append(int(index))
        if dotted:
            parts.append(dotted)
    return parts


def set_raw(doc, path, raw):
    """The document's text with the value at `path` replaced by the raw JSON text `raw`."""
    marker = "@@MARIS_FUZZ@@"
    node = doc
    parts = split_path(path)
    for p in parts[:-1]:
        node = node[p]
    node[parts[-1]] = marker
    text = json.dumps(doc, indent=1)
    return text.replace(json.dumps(marker), raw, 1).encode()


def delete_at(doc, path):
    node = doc
    parts = split_path(path)
    for p in parts[:-1]:
        node = node[p]
    del node[parts[-1]]
    return json.dumps(doc, indent=1).encode()


def copy(doc):
    return json.loads(json.dumps(doc))


def numeric_paths(doc):
    return [p for p, v in leaves(doc) if isinstance(v, (int, float)) and not isinstance(v, bool)]


def data_paths(doc):
    """Paths of text values that name data files (builtin:NAME or *.csv and similar)."""
    out = []
    for p, v in leaves(doc.get("parameters", {}), "parameters"):
        key = p.rsplit(".", 1)[-1]
        if isinstance(v, str) and (v.startswith("builtin:") or v.endswith((".csv", ".txt", ".dat")) or
                                   any(word in key for word in ("file", "stem", "directory", "record"))):
            out.append((p, v))
    return out


def bad_data_texts(rng, good):
    """Broken variants of a data file's text."""
    lines = good.splitlines() or ["a,b"]
    header = lines[0]
    ncols = max(1, header.count(",") + 1)
    variants = {
        "nan-cell": "\n".join(lines[:2] + [",".join(["nan"] * ncols)] + lines[2:]) + "\n",
        "inf-cell": "\n".join(lines[:2] + [",".join(["1e400"] * ncols)] + lines[2:]) + "\n",
        "bad-rows": header + "\n" + "x,y\n" * 10000,
        "wide-row": header + "\n" + ",".join(["1"] * 5000) + "\n",
        "empty": "",
        "header-only": header + "\n",
        "truncated": good[: max(1, len(good) // 3)],
        "binary": "".join(chr(rng.randrange(1, 256)) for _ in range(4000)),
        "huge-numbers": "\n".join([header] + [",".join(["1e300"] * ncols)] * 50) + "\n",
        "negative": "\n".join([header] + [",".join(["-1"] * ncols)] * 20) + "\n",
    }
    name = rng.choice(sorted(variants))
    return name, variants[name].encode("utf-8", "surrogateescape") if name != "binary" else \
        bytes(rng.randrange(0, 256) for _ in range(4000))


def mutate(rng, seed_doc, resources):
    """One mutant of `seed_doc` (a parsed built-in scenario)."""
    doc = copy(seed_doc)
    params = doc.get("parameters", {})
    paths = leaves(params, "parameters")
    numbers = numeric_paths(doc)
    ops = ["delete", "type", "extreme", "extreme", "scale", "huge-array", "deep", "long-string", "duplicate",
           "unknown", "garbage", "special", "data", "data", "set", "set", "set-extreme", "top"]
    op = rng.choice(ops)
    if op == "delete" and paths:
        p, _ = rng.choice(paths)
        return Case(op, p, delete_at(doc, p))
    if op == "type" and paths:
        p, _ = rng.choice(paths)
        return Case(op, p, set_raw(doc, p, rng.choice(TYPE_SWAPS)))
    if op in ("extreme", "scale") and numbers:
        p = rng.choice(numbers)
        if op == "extreme":
            raw = rng.choice(EXTREME_NUMBERS)
        else:
            v = seed_value(doc, p)
            raw = repr(float(v) * 10.0 ** rng.choice([-15, -9, -6, -3, 3, 6, 9, 15]))
        return Case(op, p, set_raw(doc, p, raw))
    if op == "huge-array" and paths:
        p, _ = rng.choice(paths)
        n = rng.choice([100000, 300000, 1200000])
        return Case(op, p, set_raw(doc, p, "[" + ",".join(["1.5"] * n) + "]"))
    if op == "deep" and paths:
        p, _ = rng.choice(paths)
        depth = rng.choice([70, 1000, 60000])
        opener, closer = rng.choice([("[", "]"), ('{"a":', "}")])
        return Case(op, p, set_raw(doc, p, opener * depth + "1" + closer * depth))
    if op == "long-string":
        p = rng.choice([p for p, _ in paths] + ["name", "description", "scene"])
        n = rng.choice([5000, 150000, 5000000])
        return Case(op, p, set_raw(doc, p, json.dumps("x" * n)))
    if op == "duplicate" and paths:
        p, v = rng.choice(paths)
        parts = split_path(p)
        if isinstance(parts[-1], str):
            text = set_raw(doc, p, json.dumps(v) + ", " + json.dumps(parts[-1]) + ": " + json.dumps(v))
            return Case(op, p, text)
    if op == "unknown":
        p, _ = rng.choice(paths) if paths else ("parameters", None)
        parent = p.rsplit(".", 1)[0] if "." in p else "parameters"
        node = doc
        try:
            for part in split_path(parent):
                node = node[part]
        except (KeyError, IndexError, TypeError):
            node = None
        if isinstance(node, dict):
            node["x" * rng.choice([3, 300000])] = 1
            return Case(op, parent, json.dumps(doc).encode())
    if op == "garbage":
        text = json.dumps(doc, indent=1).encode()
        choice = rng.choice(["truncate", "bytes", "utf8", "bom", "trailing", "nul"])
        if choice == "truncate":
            text = text[: rng.randrange(1, len(text))]
        elif choice == "bytes":
            pos = rng.randrange(len(text))
            text = text[:pos] + bytes(rng.randrange(256) for _ in range(8)) + text[pos:]
        elif choice == "utf8":
            text = text.replace(b'"name": "', b'"name": "\xff\xfe', 1)
        elif choice == "bom":
            text = b"\xef\xbb\xbf" + text
        elif choice == "trailing":
            text = text + b" {}"
        else:
            text = text.replace(b"{", b"{\x00", 1)
        return Case(op + "-" + choice, "file", text)
    if op == "special":
        return Case(op, "file", special=rng.choice(["fifo", "dir", "loop", "missing", "devzero", "empty"]))
    if op == "data":
        found = data_paths(doc)
        if found:
            p, value = rng.choice(found)
            good = read_data(resources, doc.get("scene", ""), value)
            name, content = bad_data_texts(rng, good)
            fname = "data_" + name + ".csv"
            if rng.random() < 0.2:  # not a regular file: the driver makes a FIFO or a link loop for "@..."
                fname = rng.choice(["/dev/zero", "fifo_data", "loop_data", "."])
                marks = {"fifo_data": b"@fifo", "loop_data": b"@loop"}
                return Case("data-special", p, set_raw(doc, p, json.dumps(fname)),
                            data={fname: marks[fname]} if fname in marks else {})
            return Case("data-" + name, p, set_raw(doc, p, json.dumps(fname)), data={fname: content})
    if op in ("set", "set-extreme"):
        text = json.dumps(doc, indent=1).encode()
        if op == "set-extreme" and numbers:
            p = rng.choice(numbers)
            return Case(op, p, text, sets=[p + "=" + rng.choice(EXTREME_NUMBERS)])
        p = rng.choice([p for p, _ in paths] or ["parameters.x"])
        bad = rng.choice(["deep-path", "deep-value", "huge", "overflow", "no-equals", "unknown", "into-leaf",
                          "long-value", "empty-path", "array"])
        if bad == "deep-path":
            return Case("set-" + bad, "--set", text, sets=[".".join(["a"] * 60000) + "=1"])
        if bad == "deep-value":
            return Case("set-" + bad, "--set", text, sets=[p + "=" + "[" * 60000 + "]" * 60000])
        if bad == "huge":
            return Case("set-" + bad, "--set", text, sets=[p + "=[" + ",".join(["2"] * 60000) + "]"])
        if bad == "overflow":
            return Case("set-" + bad, p, text, sets=[p + "=1e400"])
        if bad == "no-equals":
            return Case("set-" + bad, "--set", text, sets=[p])
        if bad == "unknown":
            return Case("set-" + bad, "--set", text, sets=["parameters.no_such_group.no_such_field=1"])
        if bad == "into-leaf":
            return Case("set-" + bad, p, text, sets=[p + ".deeper=1"])
        if bad == "long-value":
            return Case("set-" + bad, p, text, sets=[p + "=" + "y" * 120000])
        if bad == "empty-path":
            return Case("set-" + bad, "--set", text, sets=["=1"])
        return Case("set-" + bad, p, text, sets=[p + "=[1e308,-1e308,null]"])
    if op == "top":
        key = rng.choice(TOP_KEYS)
        raw = rng.choice(TYPE_SWAPS + ['"maris-scenario/99"', '"no_such_scene"'])
        if key in doc:
            return Case(op, key, set_raw(doc, key, raw))
    # Fallback: an extreme number somewhere.
    p = rng.choice(numbers) if numbers else "parameters"
    return Case("extreme", p, set_raw(doc, p, rng.choice(EXTREME_NUMBERS)) if numbers else b"{}")


def seed_value(doc, path):
    node = doc
    for p in split_path(path):
        node = node[p]
    return node


def read_data(resources, scene, value):
    """The text of the data file a field names; for an empty field, some CSV of the scene's data."""
    folder = os.path.join(resources, "data", scene)
    if value.startswith("builtin:"):
        path = os.path.join(folder, value[len("builtin:"):])
    elif value:
        path = value
    else:
        csvs = sorted(f for f in os.listdir(folder) if f.endswith(".csv")) if os.path.isdir(folder) else []
        path = os.path.join(folder, csvs[0]) if csvs else ""
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            return f.read(1 << 20)
    except OSError:
        return "x,y\n1,2\n"


def make_rng(seed, index):
    return random.Random(seed * 1000003 + index)
