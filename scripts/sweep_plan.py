"""What a sweep runs (scripts/sweep.py): sweep files and the command line's --deck, --parameter
and --values as entries with a value and overrides, the distinct ydry runs they need (entries
whose decks resolve alike share one), each run's state in its folder and its ydry arguments.
Also how decks are told apart (resolved_deck, deck_key, deck_digest), which
verification/peron/ and scripts/plot_sweep.py use too.
"""
import hashlib
import json
import re
import shlex
import subprocess
import sys
import tomllib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "verification"))
import ydry_case  # noqa: E402  (REPO)

REPO = ydry_case.REPO
CRACK_KINDS = ("surface", "penetrating", "network")  # network: plan-view runs (plot_sweep_network.py)
FILE_KEYS = {"name", "deck", "parameter", "axis", "unit", "scale", "cracks", "figures", "set", "values",
             "entries"}


class SweepError(Exception):
    """Bad input: the message names the file and key or the run."""


# ---- the sweeps: entries with a value and overrides ------------------------------------

def toml_value(text):
    """A value given on the command line as TOML (1e6, 0.08, "cross"); a bare word is a string."""
    try:
        return tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError:
        return text


def toml_text(value):
    """A value as --set writes it."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    return json.dumps(value)


def value_label(value):
    """A value as a folder name shows it: 1e+06, 0.004, cross."""
    text = f"{value:g}" if isinstance(value, (int, float)) and not isinstance(value, bool) else str(value)
    return re.sub(r"[^A-Za-z0-9.+-]", "_", text)


def overrides_list(where, key, value):
    if not isinstance(value, list) or not all(isinstance(v, str) and "=" in v for v in value):
        raise SweepError(f"{where}: {key}: a list of overrides \"key.path=value\"")
    return value


def load_sweep_file(path):
    """A sweep file as {name, deck, parameter, axis, unit, scale, cracks, figures, entries}, each
    entry {value, overrides}; SweepError naming the file and key on anything wrong."""
    try:
        spec = tomllib.loads(path.read_text())
    except (OSError, tomllib.TOMLDecodeError) as error:
        raise SweepError(f"{path}: {error}")
    unknown = sorted(set(spec) - FILE_KEYS)
    if unknown:
        raise SweepError(f"{path}: unknown key {unknown[0]} (keys: {', '.join(sorted(FILE_KEYS))})")
    for key in ("name", "deck", "axis"):
        if not isinstance(spec.get(key), str):
            raise SweepError(f"{path}: {key}: a string is required")
    if ("values" in spec) == ("entries" in spec):
        raise SweepError(f"{path}: give either values or [[entries]]")
    if not isinstance(spec.get("values", spec.get("entries")), list) or not spec.get("values", spec.get("entries")):
        raise SweepError(f"{path}: {'values' if 'values' in spec else 'entries'}: a list of at least one")
    if not isinstance(spec.get("scale", 1.0), (int, float)) or not isinstance(spec.get("unit", ""), str):
        raise SweepError(f"{path}: scale is a number, unit a string")
    if not all(isinstance(k, int) for k in spec.get("figures", [])):
        raise SweepError(f"{path}: figures: a list of figure numbers")
    if spec.get("cracks", "surface") not in CRACK_KINDS:
        raise SweepError(f"{path}: cracks: one of {', '.join(CRACK_KINDS)}")
    common = overrides_list(path, "set", spec.get("set", []))
    if "values" in spec:
        entries = [{"value": value, "overrides": []} for value in spec["values"]]
    else:
        entries = []
        for k, entry in enumerate(spec["entries"]):
            where = f"{path}: entries[{k}]"
            if set(entry) - {"value", "set"} or "value" not in entry:
                raise SweepError(f"{where}: an entry has a value and a set of overrides, nothing else")
            entries.append({"value": entry["value"], "overrides": overrides_list(where, "set", entry.get("set", []))})
    sweep = described(spec["name"], path.parent / spec["deck"], spec.get("parameter"), entries, common)
    sweep.update(file=str(path), axis=spec["axis"], unit=spec.get("unit", ""), scale=spec.get("scale", 1.0),
                 cracks=spec.get("cracks", "surface"), figures=spec.get("figures", []))
    return sweep


def command_line_sweep(args):
    """The sweep of --deck, --parameter and --values."""
    name = args.name or args.parameter.split(".")[-1]
    entries = [{"value": toml_value(text), "overrides": []} for text in args.values]
    sweep = described(name, args.deck, args.parameter, entries, [])
    sweep.update(file=None, axis=args.parameter, unit="", scale=1.0, cracks="surface", figures=[])
    return sweep


def described(name, deck, parameter, entries, common):
    """A sweep's runs: each entry's overrides are parameter=value, the sweep's, then its own."""
    if not re.fullmatch(r"[A-Za-z0-9_.-]+", name):
        raise SweepError(f"sweep name {name!r}: letters, digits, _ . - only (it names folders)")
    for entry in entries:
        entry["overrides"] = ([f"{parameter}={toml_text(entry['value'])}"] if parameter else []) + common \
            + entry["overrides"]
        entry["folder"] = f"{name}_{value_label(entry['value'])}"
    folders = [entry["folder"] for entry in entries]
    if len(set(folders)) != len(folders):
        raise SweepError(f"sweep {name}: two values name the same folder ({', '.join(folders)})")
    return {"name": name, "deck": str(Path(deck).resolve()), "parameter": parameter, "entries": entries}


# ---- runs: the distinct decks, their state, their ydry command -------------------------

def shown(path):
    """A path as the commands write it: relative to the repository when inside it (the SLURM
    script then runs from any clone), absolute otherwise."""
    path = Path(path).resolve()
    return str(path.relative_to(REPO)) if path.is_relative_to(REPO) else str(path)


def numbers_as_floats(value):
    """A parsed deck with its integers as floats: 600000 and 600000.0 are one end time."""
    if isinstance(value, dict):
        return {key: numbers_as_floats(item) for key, item in value.items()}
    if isinstance(value, list):
        return [numbers_as_floats(item) for item in value]
    return float(value) if isinstance(value, int) and not isinstance(value, bool) else value


def deck_key(text):
    """A resolved deck (ydry check, a run's deck.toml) as a comparable string: its values, not
    its comments or number formatting, and the mesh file by its contents where it exists here
    (the resolved deck names it by an absolute path: a run copied from a cluster keeps it)."""
    deck = numbers_as_floats(tomllib.loads(text))
    mesh = Path(deck.get("mesh", {}).get("file", ""))
    if mesh.is_file():
        deck["mesh"]["file"] = hashlib.sha256(mesh.read_bytes()).hexdigest()
    return json.dumps(deck, sort_keys=True)


def deck_digest(text):
    """A short fingerprint of deck_key(text), kept in sweep.json for each value: the run a
    value's folder holds is still that value's run only while its deck.toml has it."""
    return hashlib.sha256(deck_key(text).encode()).hexdigest()[:16]


def resolved_deck(ydry, deck, overrides):
    """`ydry check` of the deck with the overrides: the resolved deck's text; SweepError with
    ydry's message when the deck or an override is wrong."""
    cmd = [str(ydry), "check", deck] + [arg for o in overrides for arg in ("--set", o)]
    proc = subprocess.run(cmd, capture_output=True, text=True, cwd=REPO)
    if proc.returncode != 0:
        raise SweepError(f"{shlex.join(cmd)}:\n{proc.stderr.strip()}")
    return proc.stdout


def completed_runs(out):
    """{deck_key: folder name} of the completed ydry runs in OUT's folders (the first by name
    where two ran the same deck)."""
    found = {}
    for summary in sorted(out.glob("*/summary.json")) if out.is_dir() else []:
        try:
            if json.loads(summary.read_text()).get("completed") is True:
                found.setdefault(deck_key((summary.parent / "deck.toml").read_text()), summary.parent.name)
        except (OSError, ValueError, AttributeError):  # unreadable, not JSON or TOML, not a table
            continue  # not a run this sweep can reuse
    return found


def plan_runs(sweeps, out, ydry, extra):
    """The distinct runs of the sweeps, each {folder, path, deck, overrides, deck_key, end_time},
    and the entries that share one: an entry whose resolved deck is an earlier entry's shares
    that run, and so does one whose deck some other folder of OUT has completed (a sweep file
    run alone after another that ran the same deck), unless its own folder holds that run; its
    folder becomes the run's, listed as (its own folder name, the run's)."""
    runs, by_deck, shared = [], {}, []
    done = completed_runs(out)
    for sweep in sweeps:
        for entry in sweep["entries"]:
            entry["overrides"] += extra
            resolved = resolved_deck(ydry, shown(sweep["deck"]), entry["overrides"])
            key = deck_key(resolved)
            entry["deck_digest"] = deck_digest(resolved)
            if key not in by_deck and done.get(key, entry["folder"]) != entry["folder"]:
                by_deck[key] = {"folder": done[key]}  # completed, so not among the runs to make
            if key in by_deck:
                shared.append((entry["folder"], by_deck[key]["folder"]))
                entry["folder"] = by_deck[key]["folder"]
                continue
            run = {"folder": entry["folder"], "path": out / entry["folder"], "deck": shown(sweep["deck"]),
                   "overrides": entry["overrides"], "deck_key": key,
                   "end_time": float(tomllib.loads(resolved)["run"]["end_time"])}
            by_deck[key] = run
            runs.append(run)
    return runs, shared


def run_state(run):
    """new | completed | unfinished (this deck's run, not at its end) | changed (the folder holds
    the run of another deck, or something else)."""
    summary, deck = run["path"] / "summary.json", run["path"] / "deck.toml"
    if not run["path"].exists():
        return "new"
    if not deck.is_file():
        return "unfinished"  # stopped before its first output, or never a ydry run: no checkpoint
    try:
        if deck_key(deck.read_text()) != run["deck_key"]:
            return "changed"
        completed = summary.is_file() and json.loads(summary.read_text()).get("completed") is True
    except (tomllib.TOMLDecodeError, json.JSONDecodeError):
        return "changed"
    return "completed" if completed else "unfinished"


def newest_checkpoint(folder):
    """The checkpoint of the most coupling steps in FOLDER/checkpoints (NAME_NNNNNN.chk, NNNNNN
    the steps done), or None."""
    found = [(int(match.group(1)), path) for path in (folder / "checkpoints").glob("*.chk")
             if (match := re.search(r"_(\d+)\.chk$", path.name))]
    return max(found)[1] if found else None


def resume_arguments(run, state):
    """How ydry takes up a run: an unfinished run of this deck goes on from its newest checkpoint
    (`--restart`: ydry takes the folder's files back to it, and refuses a deck that is not the
    checkpoint's); any other run starts at t = 0, `--force` letting it replace what the folder
    holds. The SLURM script makes the same choice in bash (write_slurm)."""
    checkpoint = newest_checkpoint(run["path"]) if state == "unfinished" else None
    return ["--restart", shown(checkpoint)] if checkpoint else ["--force"]


def run_arguments(run, checkpoint_every):
    """The ydry arguments of a run but the resume ones: deck, folder, overrides. ydry writes a
    checkpoint every checkpoint_every seconds of wall time (0: only at the end and when stopped)."""
    sets = [arg for override in run["overrides"] for arg in ("--set", override)]
    every = ["--checkpoint-every", f"{checkpoint_every:g}"] if checkpoint_every > 0 else []
    return [run["deck"], "-o", shown(run["path"]), "--quiet", *every, *sets]
