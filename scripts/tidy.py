#!/usr/bin/env python3
"""clang-tidy over every first-party translation unit of a compile database.

    tidy.py --src DIR --build DIR --cache DIR [--verified FILE] [--record] [--jobs N]
            [--known-only]

A unit is identified by a key: a hash of the clang-tidy version, every .clang-tidy, the
analyzer flags, the unit's path and compile command (source and build dirs made relative),
and its `clang++-14 -E` output plus the text of every first-party file it includes (so
editing a header, or a NOLINT comment in it, changes the key of every unit that includes it).

A unit is analysed unless its key is already known clean:
  - in the local cache (CACHE/clean/KEY), written after every clean analysis; or
  - in the committed record (--verified, scripts/tidy-verified.txt), the keys of a whole-tree
    run that reported nothing, written by --record. A fresh machine with nothing cached then
    analyses only the units whose key changed since that run, so the stage's cost follows the
    change, not the tree; a unit never analysed has no key in either and is analysed.
The preprocessed hash is itself cached like ccache's direct mode: a manifest per compile
command lists every file the unit read, and when none changed the preprocessor is not run.

--record rewrites the --verified file with every unit's key, and only when the run found
nothing. Exit status: 0 clean, 1 diagnostics (printed once per location), 2 bad usage.

--known-only analyses nothing. With --record it writes the units already known clean (cached
or recorded) and says how many are not: for a whole-tree analysis cut short (the end of a
session on a slow machine), so that what it verified is not lost to a machine with an empty
cache. It checks nothing and always exits 0; the stage itself never passes it.
"""
import argparse
import concurrent.futures
import hashlib
import json
import os
import re
import shlex
import subprocess
import sys
import threading
import time
from collections import Counter

TIDY, CLANG = "clang-tidy-14", "clang++-14"
FIRST_PARTY = ("sim", "assessment", "app", "tests")
# gcc-only warning flags in a g++ compile database must not stop clang
EXTRA = ["-Wno-unknown-warning-option", "-Wno-unused-command-line-argument"]
# the static analyzer's default inlining costs 3-4x its shallow mode on the engine's Eigen code,
# which the CI time budget cannot pay for every file
ANALYZER = ["-Xclang", "-analyzer-config", "-Xclang", "mode=shallow"]
LINE_MARKER = re.compile(rb'^# \d+ "([^"]+)"', re.M)
DIAGNOSTIC = re.compile(r"^(/[^:]+):(\d+):(\d+): (warning|error): (.*?)(?: \[([^\]]+)\])?$")


def sha(*parts):
    h = hashlib.sha256()
    for p in parts:
        h.update(p if isinstance(p, bytes) else p.encode())
        h.update(b"\0")
    return h.hexdigest()


def is_under(path, root):
    return os.path.commonpath([path, root]) == root


def args_of(entry):
    if "arguments" in entry:
        return list(entry["arguments"])
    return shlex.split(entry["command"])


class Tree:
    """The source and build dirs, and how paths in them are written machine-independently."""

    def __init__(self, src, build):
        self.src, self.build = src, build
        self._hashes, self._lock = {}, threading.Lock()

    def relative(self, text):
        # the build dir may sit inside the source dir: replace the longer path first
        pairs = sorted(((self.build, "<build>"), (self.src, "<src>")), key=lambda x: -len(x[0]))
        for path, name in pairs:
            text = text.replace(path, name)
        return text

    def expand(self, text):
        return text.replace("<build>", self.build).replace("<src>", self.src)

    def first_party(self, path):
        rel = os.path.relpath(path, self.src)
        return (not rel.startswith("..") and not is_under(path, self.build)
                and rel.split(os.sep)[0] in FIRST_PARTY)

    def file_hash(self, path):
        with self._lock:
            if path in self._hashes:
                return self._hashes[path]
        try:
            with open(path, "rb") as f:
                value = hashlib.sha256(f.read()).hexdigest()
        except OSError:
            value = "missing"
        with self._lock:
            self._hashes[path] = value
        return value

    def config_key(self):
        version = subprocess.run([TIDY, "--version"], capture_output=True, text=True,
                                 check=True).stdout
        # LLVM's version text names the CPU it runs on ("Host CPU: cascadelake"): the tool is the
        # same on every machine, and keyed with it a record made on one machine was void on the
        # next (every unit analysed again, ~40 min of CI)
        version = "\n".join(line for line in version.splitlines() if "Host CPU" not in line)
        configs = []
        for root, dirs, files in os.walk(self.src):
            dirs[:] = sorted(d for d in dirs
                             if not d.startswith(".") and not d.startswith("build")
                             and not is_under(os.path.join(root, d), self.build))
            if ".clang-tidy" in files:
                with open(os.path.join(root, ".clang-tidy"), "rb") as f:
                    configs.append(self.relative(root) + "\n" + f.read().decode())
        return sha(version, " ".join(ANALYZER), *sorted(configs))


UNITY_INCLUDE = re.compile(r'^#include "([^"]+)"', re.M)


def units_of(tree):
    """First-party sources of the compile database, one per file, no generated code: path ->
    (directory, the compile command without its input and output). A unity build's batch
    (CMake's Unity/unity_N_cxx.cxx, a list of #includes) stands for each source it includes,
    compiled with the batch's command."""
    with open(os.path.join(tree.build, "compile_commands.json")) as f:
        database = json.load(f)
    units = {}
    for entry in database:
        directory = entry["directory"]
        path = os.path.normpath(os.path.join(directory, entry["file"]))
        sources = [path]
        if re.search(r"/Unity/unity_\d+_cxx\.cxx$", path):
            with open(path) as f:
                sources = [os.path.normpath(os.path.join(os.path.dirname(path), s))
                           for s in UNITY_INCLUDE.findall(f.read())]
        flags = without_input_and_output(args_of(entry), entry["file"], path)
        for source in sources:
            if tree.first_party(source) and "_autogen" not in source and source not in units:
                units[source] = (directory, flags)
    return units


def without_input_and_output(args, *inputs):
    flags, skip = [], False
    for a in args:
        if skip:
            skip = False
        elif a == "-o":
            skip = True
        elif a != "-c" and not a.startswith("-o") and a not in inputs:
            flags.append(a)
    return flags


class Keys:
    """Each unit's key, through the preprocessor or the manifest of its last run."""

    def __init__(self, tree, cache, config_key):
        self.tree, self.cache, self.config_key = tree, cache, config_key
        os.makedirs(os.path.join(cache, "manifest"), exist_ok=True)

    def of(self, path, unit):
        t = self.tree
        directory, flags = unit
        command = t.relative(" ".join(flags)) + "\n" + t.relative(directory)
        command_key = sha(self.config_key, t.relative(path), command)
        pp = self._preprocessed_hash(unit, path, command_key)
        return sha(command_key, pp) if pp else None

    def _preprocessed_hash(self, unit, path, command_key):
        t = self.tree
        manifest = os.path.join(self.cache, "manifest", command_key)
        try:
            with open(manifest) as f:
                known = json.load(f)
            if all(t.file_hash(t.expand(p)) == h for p, h in known["deps"].items()):
                return known["pp"]
        except (OSError, ValueError, KeyError):
            pass
        pp, deps = self._preprocess(unit, path)
        if pp is None:
            return None
        with open(manifest + ".tmp", "w") as f:
            json.dump({"pp": pp, "deps": {t.relative(d): t.file_hash(d) for d in deps}}, f)
        os.replace(manifest + ".tmp", manifest)
        return pp

    def _preprocess(self, unit, path):
        """Hash of the unit's preprocessed text and of the first-party files it includes, and
        every file it read."""
        t = self.tree
        directory, flags = unit
        run = subprocess.run([CLANG] + flags[1:] + EXTRA + ["-E", path], cwd=directory,
                             capture_output=True)
        if run.returncode != 0:
            return None, None
        deps = {path}
        for m in LINE_MARKER.finditer(run.stdout):
            name = m.group(1).decode(errors="replace")
            if not name.startswith("<"):
                deps.add(os.path.normpath(os.path.join(directory, name)))
        # comments are gone from -E output: the first-party text carries the NOLINTs
        mine = [t.relative(d) + t.file_hash(d) for d in sorted(deps) if is_under(d, t.src)]
        return sha(t.relative(run.stdout.decode(errors="replace")), *mine), sorted(deps)


def diagnostics(tree, output):
    """Blocks of (first line, check, text) for diagnostics in first-party files."""
    blocks, current = [], None
    for line in output.splitlines():
        m = DIAGNOSTIC.match(line)
        if m:
            current = None
            if tree.first_party(os.path.normpath(m.group(1))):
                current = [tree.relative(line), m.group(6) or "clang-diagnostic-" + m.group(4),
                           [line]]
                blocks.append(current)
        elif current is not None and not re.match(r"^\d+ (warning|error)s? generated", line):
            current[2].append(line)
    return blocks


def write_database(tree, units, folder):
    """The per-source compile database clang-tidy reads (a unity build's has only batches)."""
    os.makedirs(folder, exist_ok=True)
    entries = [{"directory": d, "file": p, "arguments": flags + ["-c", p]}
               for p, (d, flags) in sorted(units.items())]
    with open(os.path.join(folder, "compile_commands.json.tmp"), "w") as f:
        json.dump(entries, f, indent=1)
    os.replace(os.path.join(folder, "compile_commands.json.tmp"),
               os.path.join(folder, "compile_commands.json"))


def analyse(tree, database, path):
    run = subprocess.run([TIDY, "-p", database, "--quiet"]
                         + [f"--extra-arg={a}" for a in EXTRA + ANALYZER] + [path],
                         capture_output=True, text=True)
    found = diagnostics(tree, run.stdout + "\n" + run.stderr)
    if run.returncode != 0 and not found:
        found = [[tree.relative(path), "clang-tidy-failed",
                  [f"{path}: clang-tidy exited with {run.returncode}", run.stdout, run.stderr]]]
    return found


def read_verified(path):
    """The keys of the committed record, and the commit it names (for the summary)."""
    keys, commit = set(), "?"
    if not path or not os.path.exists(path):
        return keys, commit
    with open(path) as f:
        for line in f:
            line = line.strip()
            m = re.match(r"^# commit: (\S+)", line)
            if m:
                commit = m.group(1)
            elif line and not line.startswith("#"):
                keys.add(line.split()[0])
    return keys, commit


def write_verified(path, tree, keyed):
    head = subprocess.run(["git", "-C", tree.src, "rev-parse", "--short", "HEAD"],
                          capture_output=True, text=True).stdout.strip() or "unknown"
    dirty = subprocess.run(["git", "-C", tree.src, "status", "--porcelain", "--untracked-files=no"],
                           capture_output=True, text=True).stdout.strip()
    with open(path + ".tmp", "w") as f:
        f.write("# Translation units in which clang-tidy-14 (scripts/tidy.sh) found nothing, one\n"
                "# per line: its key, then its path. A unit whose key is here is not analysed\n"
                "# again; any change to it, to a header it includes, to its compile command, to\n"
                "# .clang-tidy or to the tool gives it another key. Rewritten by\n"
                "# `bash scripts/tidy.sh --record` after a run that reported nothing.\n")
        f.write(f"# commit: {head}{' (with uncommitted changes)' if dirty else ''}\n")
        for rel, key in sorted((os.path.relpath(p, tree.src), k) for p, k in keyed.items()):
            f.write(f"{key} {rel}\n")
    os.replace(path + ".tmp", path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--src", required=True)
    parser.add_argument("--build", required=True)
    parser.add_argument("--cache", required=True)
    parser.add_argument("--verified", help="the committed record of clean keys")
    parser.add_argument("--record", action="store_true",
                        help="rewrite --verified with every unit's key when nothing is found")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--known-only", action="store_true",
                        help="analyse nothing: with --record, write the units already known clean "
                             "(in the cache or the record) and name how many are not; not a check")
    o = parser.parse_args()
    if o.record and not o.verified:
        parser.error("--record needs --verified FILE")
    start = time.monotonic()
    tree = Tree(os.path.realpath(o.src), os.path.realpath(o.build))
    units = units_of(tree)
    if not units:
        print(f"tidy: no first-party translation unit in {tree.build}/compile_commands.json",
              file=sys.stderr)
        return 2
    os.makedirs(os.path.join(o.cache, "clean"), exist_ok=True)
    keys = Keys(tree, o.cache, tree.config_key())
    database = os.path.join(o.cache, "database", sha(tree.build)[:16])
    write_database(tree, units, database)
    verified, verified_commit = read_verified(o.verified)

    def check(path):
        key = keys.of(path, units[path])
        if key and os.path.exists(os.path.join(o.cache, "clean", key)):
            return path, key, "cache", []
        if key and key in verified:
            return path, key, "record", []
        if o.known_only:
            return path, key, "unknown", []
        found = analyse(tree, database, path)
        if not found and key:
            open(os.path.join(o.cache, "clean", key), "w").close()
        return path, key, "analysed", found

    how, seen, checks, keyed, unknown = Counter(), set(), Counter(), {}, set()
    with concurrent.futures.ThreadPoolExecutor(o.jobs) as pool:
        for path, key, source, found in pool.map(check, sorted(units)):
            how[source] += 1
            if key:
                keyed[path] = key
            if source == "analysed":
                print(f"tidy: analysed {os.path.relpath(path, tree.src)}", flush=True)
            if source == "unknown":
                unknown.add(path)
            for head, name, text in found:
                # a header's diagnostic comes once per unit that includes it: show it once
                if head not in seen:
                    seen.add(head)
                    checks[name] += 1
                    print("\n".join(text), flush=True)

    if o.known_only:
        # bookkeeping after an analysis cut short (a session's end): the record keeps every
        # unit found clean so far, so a machine with nothing cached analyses only the rest
        clean = {p: k for p, k in keyed.items() if p not in unknown}
        print(f"tidy: {len(clean)} of {len(units)} units known clean, {len(units) - len(clean)} not yet analysed")
        if o.record:
            write_verified(o.verified, tree, clean)
            print(f"tidy: recorded {len(clean)} clean units in {o.verified}")
        return 0

    cpu = os.times()
    print(f"tidy: {len(units)} files: {how['analysed']} analysed, {how['record']} verified "
          f"clean at {verified_commit} (the record), {how['cache']} from the local cache; "
          f"{time.monotonic() - start:.0f} s "
          f"({cpu.children_user + cpu.children_system:.0f} s CPU)", end="")
    if seen:
        print(f"; {len(seen)} diagnostics: "
              + ", ".join(f"{n} {c}" for c, n in checks.most_common()))
        return 1
    print("; no diagnostics")
    if o.record:
        if len(keyed) != len(units):
            print("tidy: some units could not be preprocessed; the record was not written",
                  file=sys.stderr)
            return 1
        write_verified(o.verified, tree, keyed)
        print(f"tidy: recorded {len(keyed)} clean units in {o.verified}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
