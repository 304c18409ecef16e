#!/usr/bin/env python3
"""Deterministic, seeded mutation fuzzer for `maris-cli run` (Python 3 standard library only).

Seeds are every built-in scenario (`maris-cli list`, `maris-cli show NAME`), each as a short copy
(short_runs.py: short simulated time, coarse grid; a valid mutant runs to its end and its output is
checked). Each mutant (see mutators.py: deleted keys, swapped types, extreme numbers, huge arrays, deep
nesting, long strings, duplicate keys, garbage bytes, FIFOs / devices / folders / link loops, broken data
files, bad --set) runs as `maris-cli run FILE [--set ...] --out DIR --no-plots` in its own folder under a per-case time
limit. Outcomes:

  accepted: ok (exit 0, finite summary.json and CSVs), input-error (exit 2 naming a field or file),
            solver-error (exit 3, "solver failure: ..."), slow-cancelled (over the time limit, then
            honoured SIGINT with exit 130)
  defects:  crash (signal), sanitizer (ASan/UBSan/LSan report), internal (exit 1, an uncaught
            exception's text, or a library message in an exit 2/3 message), nonfinite (NaN/Inf in a
            successful run's output), unnamed (exit 2 naming no field or file), hang (ignored SIGINT),
            unexpected (any other exit)

Exit status 0 when no defect was found, 1 otherwise. Defective cases are kept under --work with the
command to reproduce them. The same --seed and --count give the same mutants.

  fuzz_cli.py --cli build/asan/app/maris-cli --count 500 --seed 1 --work /tmp/maris-fuzz
"""

import argparse
import concurrent.futures
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mutators  # noqa: E402
import short_runs  # noqa: E402

ACCEPTED = ("ok", "input-error", "solver-error", "slow-cancelled")
SANITIZER = re.compile(r"ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:|UndefinedBehaviorSanitizer")
LIBRARY_TEXT = re.compile(r"json\.exception|std::|basic_string|vector::|bad_alloc|terminate called|what\(\)")
NAMED = re.compile(r"^\s+(\S[^\n]*?)(?: = [^\n]*)?: ", re.M)


def run_case(cli, case_dir, args, timeout, env, grace=5.0, mem_mb=0):
    """Runs maris-cli in its own session; SIGINT at the limit, SIGKILL after `grace`."""
    def limit():
        if mem_mb:
            import resource
            resource.setrlimit(resource.RLIMIT_AS, (mem_mb << 20, mem_mb << 20))
    t0 = time.monotonic()
    with open(os.path.join(case_dir, "stderr.txt"), "wb") as err, open(os.path.join(case_dir, "stdout.txt"), "wb") as out:
        proc = subprocess.Popen([cli] + args, cwd=case_dir, stdout=out, stderr=err, env=env, start_new_session=True,
                                preexec_fn=limit if mem_mb else None)
        interrupted = killed = False
        try:
            code = proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            interrupted = True
            os.killpg(proc.pid, signal.SIGINT)
            try:
                code = proc.wait(timeout=grace)
            except subprocess.TimeoutExpired:
                killed = True
                os.killpg(proc.pid, signal.SIGKILL)
                code = proc.wait()
    with open(os.path.join(case_dir, "stderr.txt"), "rb") as f:
        stderr = f.read(1 << 20).decode("utf-8", "replace")
    return {"code": code, "interrupted": interrupted, "killed": killed, "stderr": stderr,
            "wall": time.monotonic() - t0}


def finite_cell(text):
    try:
        return math.isfinite(float(text))
    except ValueError:
        return False


def nonfinite_output(out_dir):
    """The first non-finite value in summary.json or a CSV (a column's trailing padding excepted), or ''."""
    try:
        with open(os.path.join(out_dir, "summary.json"), encoding="utf-8") as f:
            summary = json.load(f)
    except (OSError, ValueError) as e:
        return f"summary.json unreadable: {e}"
    for name, entry in summary.get("results", {}).items():
        v = entry.get("value")
        if not isinstance(v, (int, float)) or not math.isfinite(v):
            return f"summary.json results.{name} = {v}"
    for fname in sorted(os.listdir(out_dir)):
        if not fname.endswith(".csv"):
            continue
        with open(os.path.join(out_dir, fname), encoding="utf-8") as f:
            rows = [line.rstrip("\n").split(",") for line in f][2:]
        for c in range(len(rows[0]) if rows else 0):
            finite = [finite_cell(r[c] if c < len(r) else "nan") for r in rows]
            if False in finite and True in finite[finite.index(False):]:
                return f"{fname} column {c + 1} row {finite.index(False) + 3}"
    return ""


def classify(result, out_dir):
    code, stderr = result["code"], result["stderr"]
    if SANITIZER.search(stderr):
        return "sanitizer"
    if result["killed"]:
        return "hang"
    if result["interrupted"] and code == 130:
        return "slow-cancelled"
    # Any other exit after SIGINT: the run reached its own end (results, an input or solver error) before its
    # next cancellation check, within the grace; it is judged as that end.
    if code < 0:
        return "crash"
    if LIBRARY_TEXT.search(stderr):
        return "internal"
    if code == 0:
        return "nonfinite" if nonfinite_output(out_dir) else "ok"
    if code == 2:
        return "input-error" if "invalid input:" in stderr and NAMED.search(stderr.split("invalid input:", 1)[1]) \
            else "unnamed"
    if code == 3:
        return "solver-error" if "solver failure:" in stderr else "internal"
    if code == 1:
        return "internal"
    return "unexpected"


def materialise(case, case_dir):
    """Writes the scenario (or makes the special path) and data files; returns the FILE argument."""
    for name, content in case.data.items():
        path = os.path.join(case_dir, name)
        if content == b"@fifo":
            os.mkfifo(path)
        elif content == b"@loop":
            os.symlink(name, path)
        else:
            with open(path, "wb") as f:
                f.write(content)
    target = os.path.join(case_dir, "scenario.json")
    if case.special == "fifo":
        os.mkfifo(target)
    elif case.special == "dir":
        os.mkdir(target)
    elif case.special == "loop":
        os.symlink("scenario.json", target)
    elif case.special == "missing":
        target = os.path.join(case_dir, "missing.json")
    elif case.special == "devzero":
        target = "/dev/zero"
    else:
        with open(target, "wb") as f:
            f.write(case.text)
    return target


def load_seeds(cli, env, pool):
    """Every built-in scenario, parsed."""
    listing = subprocess.run([cli, "list"], capture_output=True, text=True, env=env, timeout=120, check=True).stdout
    names = [line.split()[0] for line in listing.splitlines()[1:] if line.strip()]

    def show(name):
        text = subprocess.run([cli, "show", name], capture_output=True, text=True, env=env, timeout=120, check=True).stdout
        return json.loads(text)
    return dict(zip(names, pool.map(show, names)))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", required=True, help="path to maris-cli (Release or ASan+UBSan build)")
    ap.add_argument("--count", type=int, default=500, help="mutants to run")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=10.0, help="seconds per case before SIGINT")
    ap.add_argument("--grace", type=float, default=5.0,
                    help="seconds a run may take to honour SIGINT before it counts as a hang (sanitizers are slower)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--work", default="", help="folder for cases (default: a temporary folder, removed)")
    ap.add_argument("--resources", default=os.path.join(here, "..", "..", "resources"))
    ap.add_argument("--mem-mb", type=int, default=0, help="address-space limit per run (0: none; not with ASan)")
    ap.add_argument("--keep-all", action="store_true", help="keep every case folder, not only defects")
    args = ap.parse_args()

    env = dict(os.environ)
    env.setdefault("ASAN_OPTIONS", "detect_leaks=1:abort_on_error=0:halt_on_error=1")
    env.setdefault("UBSAN_OPTIONS", "print_stacktrace=1:halt_on_error=1")
    cli = os.path.abspath(args.cli)
    work = args.work or tempfile.mkdtemp(prefix="maris-fuzz-")
    os.makedirs(work, exist_ok=True)
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs)
    seeds, full_size = short_runs.short_seeds(cli, env, load_seeds(cli, env, pool), os.path.join(work, "seeds"))
    names = sorted(seeds)

    def one(index):
        rng = mutators.make_rng(args.seed, index)
        name = names[index % len(names)]  # every built-in scenario in turn
        case = mutators.mutate(rng, seeds[name], args.resources)
        case_dir = os.path.join(work, f"case{index:05d}")
        shutil.rmtree(case_dir, ignore_errors=True)
        os.makedirs(case_dir)
        target = materialise(case, case_dir)
        cli_args = ["run", target] + [a for s in case.sets for a in ("--set", s)] + ["--out", "out", "--no-plots"]
        result = run_case(cli, case_dir, cli_args, args.timeout, env, grace=args.grace, mem_mb=args.mem_mb)
        outcome = classify(result, os.path.join(case_dir, "out"))
        record = {"index": index, "seed_scenario": name, "scene": seeds[name].get("scene", "?"), "kind": case.kind,
                  "target": case.target[:200], "outcome": outcome, "code": result["code"],
                  "wall": round(result["wall"], 2), "message": result["stderr"].strip()[-400:]}
        if outcome in ACCEPTED and not args.keep_all:
            shutil.rmtree(case_dir, ignore_errors=True)
        else:
            with open(os.path.join(case_dir, "reproduce.sh"), "w") as f:
                f.write("cd " + case_dir + " && " + " ".join(json.dumps(a) for a in [cli] + cli_args) + "\n")
        return record

    t0 = time.monotonic()
    with pool:
        records = list(pool.map(one, range(args.count)))
    with open(os.path.join(work, "results.jsonl"), "w") as f:
        for r in records:
            f.write(json.dumps(r) + "\n")

    outcomes = sorted({r["outcome"] for r in records}, key=lambda o: (o not in ACCEPTED, o))
    scenes = sorted({r["scene"] for r in records})
    print(f"{args.count} mutants of {len(names)} built-in scenarios, seed {args.seed}, "
          f"{time.monotonic() - t0:.0f} s; work folder {work}")
    if full_size:
        print("at full size (their short copies are invalid): " + ", ".join(full_size))
    print("| scene | " + " | ".join(outcomes) + " |")
    print("|---|" + "---|" * len(outcomes))
    for s in scenes + ["all"]:
        row = [sum(1 for r in records if (s == "all" or r["scene"] == s) and r["outcome"] == o) for o in outcomes]
        print(f"| {s} | " + " | ".join(str(n) for n in row) + " |")
    defects = [r for r in records if r["outcome"] not in ACCEPTED]
    for r in defects[:40]:
        print(f"DEFECT {r['outcome']}: case{r['index']:05d} {r['seed_scenario']} {r['kind']} {r['target'][:80]} "
              f"exit {r['code']}: {r['message'][-200:]!r}")
    if not args.work and not defects:
        shutil.rmtree(work, ignore_errors=True)
    return 1 if defects else 0


if __name__ == "__main__":
    sys.exit(main())
