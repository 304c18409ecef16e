"""Short copies of the built-in scenarios for fuzz_cli.py (Python 3 standard library only).

A mutant's worth lies in reaching the reader and the validator (and, when valid, the set-up and the first
steps of the solver) with an input no one wrote by hand; running the seed's full time history after that
repeats the same code paths. So each seed is fuzzed as a copy with a short simulated time, a coarser grid
and short sweeps: valid mutants then finish, and their summary.json and tables are checked for non-finite
values, where a run at the seed's full size would be cancelled at the time limit with nothing checked.
Under the sanitizers the built-in scenarios take up to minutes each; their short copies take a few seconds.
A mutant may still set any of these fields to any value (the mutation is applied to the short copy).
"""

import json
import os
import subprocess

# scene -> field (dotted path below "parameters") -> cap. A number is an upper bound (a smaller value is
# kept); a list cap keeps that many leading entries. Fields that must lie within the simulated time are
# capped with it; ship grids keep their 4m+1 stations and odd waterlines.
CAPS = {
    "riser": {"geometry.segment_count": 25, "solver.end_time": 0.05, "fatigue.start_time": 0.025,
              "output.frame_count": 10, "stress_convergence.segment_counts": 1,
              "frequency_sweep.segment_counts": 2, "frequency_sweep.pretension_ratios": 2},
    "seismic": {"solver.duration": 0.8, "solver.cutoff_frequency": 2.5, "incidence.sweep_angles_deg": 2},
    "ship": {"speed.count": 5, "numerics.stations": 65, "numerics.waterlines": 13},
    "fiv": {"sweep.speed_count": 5, "numerics.max_cycles": 20, "detail.cycles": 8, "calibration.max_iterations": 3},
    "wec": {"time.duration": 20.0, "frequency.count": 40},
    "tether": {"simulation.duration": 2.0},
}


def move_riser_point_loads(before, after):
    """A riser's point loads stay at the same place along it when its segment count is capped: joint k of n
    segments (joints 0 .. n + 1, the last one the bottom end) becomes joint round(k (n' + 1) / (n + 1))."""
    old_n = before.get("geometry", {}).get("segment_count")
    new_n = after.get("geometry", {}).get("segment_count")
    if not isinstance(old_n, int) or not isinstance(new_n, int) or old_n == new_n:
        return
    for load in after.get("point_loads", []):
        if isinstance(load, dict) and isinstance(load.get("node"), int):
            load["node"] = round(load["node"] * (new_n + 1) / (old_n + 1))


def shortened(doc):
    """A copy of `doc` (a parsed scenario) with the caps of its scene applied."""
    original = doc
    doc = json.loads(json.dumps(doc))
    for path, cap in CAPS.get(doc.get("scene", ""), {}).items():
        node = doc.get("parameters", {})
        *parents, key = path.split(".")
        for p in parents:
            node = node.get(p) if isinstance(node, dict) else None
        if not isinstance(node, dict) or key not in node:
            continue
        value = node[key]
        if isinstance(value, list):
            node[key] = value[:cap]
        elif isinstance(value, (int, float)) and not isinstance(value, bool) and value > cap:
            node[key] = type(value)(cap)
    if doc.get("scene") == "riser":
        move_riser_point_loads(original.get("parameters", {}), doc.get("parameters", {}))
    return doc


def short_seeds(cli, env, seeds, folder):
    """{name: short copy} where `maris-cli validate` accepts the copy, else the seed itself (a cap that a
    seed's other fields contradict, e.g. a point load on a joint beyond the capped segment count), and the
    names of the seeds kept at full size."""
    os.makedirs(folder, exist_ok=True)
    paths = {}
    for name, doc in seeds.items():
        paths[name] = os.path.join(folder, name + ".json")
        with open(paths[name], "w", encoding="utf-8") as f:
            json.dump(shortened(doc), f, indent=1)
    report = subprocess.run([cli, "validate"] + list(paths.values()), capture_output=True, text=True, env=env,
                            timeout=300).stdout
    valid = {line.split(": valid", 1)[0] for line in report.splitlines() if ": valid scenario" in line}
    out, full = {}, []
    for name, path in paths.items():
        if path in valid:
            with open(path, encoding="utf-8") as f:
                out[name] = json.load(f)
        else:
            out[name] = seeds[name]
            full.append(name)
    return out, full
