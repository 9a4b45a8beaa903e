#!/usr/bin/env bash
# Runs clang-tidy-14 with the project's .clang-tidy over every first-party translation unit
# (sim/, assessment/, app/, tests/) of BUILD_DIR's compile_commands.json, two at a time, and
# fails with the diagnostics printed if any is reported.
#
#   scripts/tidy.sh [BUILD_DIR]        (default: build/release, the README's build)
#
# A clean result is cached per TU under ${XDG_CACHE_HOME:-$HOME/.cache}/microsim/tidy/, keyed
# by a hash of the clang-tidy version, every .clang-tidy, the TU's compile command with the
# source and build dirs made relative, and its `clang++-14 -E` output plus the text of every
# first-party file it includes (so editing a header, or a NOLINT comment, invalidates it).
# Like ccache's direct mode, a manifest remembers which files each TU included: when none of
# them changed, the preprocessed hash is reused without running the preprocessor again.
# Needs the packages clang-tidy-14 and clang-14; the build dir must have been built (or at
# least its *_autogen targets), which this script does if generated sources are missing.
set -euo pipefail
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$src/build/release}"
if [ ! -d "$build" ]; then
  echo "tidy: build dir $build does not exist; configure and build it first" >&2
  exit 2
fi
build="$(cd "$build" && pwd)"

# the compile database is opt-in in CMake: turn it on for this build dir if it is off
if [ ! -f "$build/compile_commands.json" ]; then
  cmake -S "$src" -B "$build" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null
fi
# sources added since the last build are only in the database once CMake re-globbed
if [ -f "$build/build.ninja" ]; then
  ninja -C "$build" build.ninja >/dev/null
fi
# moc/uic output is included by our sources: generate it if this build dir never was built
# (the *_autogen targets first build the libraries their target links, so only when missing)
if [ -f "$build/build.ninja" ] && ! compgen -G "$build/app/*_autogen/include" >/dev/null; then
  mapfile -t autogen < <(ninja -C "$build" -t targets all 2>/dev/null |
    sed -n 's/^\([A-Za-z0-9_.-]*_autogen\): phony$/\1/p' | sort -u)
  if [ ${#autogen[@]} -gt 0 ]; then
    cmake --build "$build" -j 2 --target "${autogen[@]}" >/dev/null
  fi
fi

cache="${XDG_CACHE_HOME:-$HOME/.cache}/microsim/tidy"
exec python3 - "$src" "$build" "$cache" <<'PY'
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

SRC, BUILD, CACHE = sys.argv[1], sys.argv[2], sys.argv[3]
TIDY, CLANG = "clang-tidy-14", "clang++-14"
JOBS = 2
FIRST_PARTY = ("sim", "assessment", "app", "tests")
# gcc-only warning flags in a g++ compile database must not stop clang
EXTRA = ["-Wno-unknown-warning-option", "-Wno-unused-command-line-argument"]
# the static analyzer's default inlining costs 3-4x its shallow mode on the engine's Eigen code,
# which the CI time budget cannot pay for 235 files
ANALYZER = ["-Xclang", "-analyzer-config", "-Xclang", "mode=shallow"]
start = time.monotonic()


def sha(*parts):
    h = hashlib.sha256()
    for p in parts:
        h.update(p if isinstance(p, bytes) else p.encode())
        h.update(b"\0")
    return h.hexdigest()


def relative(text):
    # the build dir may sit inside the source dir: replace the longer path first
    for path, name in sorted(((BUILD, "<build>"), (SRC, "<src>")), key=lambda x: -len(x[0])):
        text = text.replace(path, name)
    return text


def first_party(path):
    rel = os.path.relpath(path, SRC)
    return (not rel.startswith("..") and not is_under(path, BUILD)
            and rel.split(os.sep)[0] in FIRST_PARTY)


def is_under(path, root):
    return os.path.commonpath([path, root]) == root


def args_of(entry):
    if "arguments" in entry:
        return list(entry["arguments"])
    return shlex.split(entry["command"])


# the translation units: first-party sources, one entry per file, no generated code
with open(os.path.join(BUILD, "compile_commands.json")) as f:
    database = json.load(f)
units = {}
for entry in database:
    path = os.path.normpath(os.path.join(entry["directory"], entry["file"]))
    if first_party(path) and "_autogen" not in path and path not in units:
        units[path] = entry
if not units:
    sys.exit(f"tidy: no first-party translation unit in {BUILD}/compile_commands.json")

version = subprocess.run([TIDY, "--version"], capture_output=True, text=True,
                         check=True).stdout
configs = []
for root, dirs, files in os.walk(SRC):
    dirs[:] = sorted(d for d in dirs
                     if not d.startswith(".") and not is_under(os.path.join(root, d), BUILD)
                     and not d.startswith("build"))
    if ".clang-tidy" in files:
        with open(os.path.join(root, ".clang-tidy"), "rb") as f:
            configs.append(relative(root) + "\n" + f.read().decode())
config_key = sha(version, *sorted(configs))
os.makedirs(os.path.join(CACHE, "clean"), exist_ok=True)
os.makedirs(os.path.join(CACHE, "manifest"), exist_ok=True)

file_hashes = {}
hash_lock = threading.Lock()


def file_hash(path):
    with hash_lock:
        if path in file_hashes:
            return file_hashes[path]
    try:
        with open(path, "rb") as f:
            value = hashlib.sha256(f.read()).hexdigest()
    except OSError:
        value = "missing"
    with hash_lock:
        file_hashes[path] = value
    return value


LINE_MARKER = re.compile(rb'^# \d+ "([^"]+)"', re.M)


def preprocess(entry, path):
    """Hash of the TU's preprocessed text and the first-party files it includes, and the
    list of every file it read (for the manifest)."""
    args = args_of(entry)
    args[0] = CLANG
    out = []
    skip = False
    for a in args[1:]:
        if skip:
            skip = False
        elif a == "-o":
            skip = True
        elif a != "-c" and not a.startswith("-o"):
            out.append(a)
    run = subprocess.run([CLANG] + out + EXTRA + ["-E"], cwd=entry["directory"],
                         capture_output=True)
    if run.returncode != 0:
        return None, None
    deps = set()
    for m in LINE_MARKER.finditer(run.stdout):
        name = m.group(1).decode(errors="replace")
        if not name.startswith("<"):
            deps.add(os.path.normpath(os.path.join(entry["directory"], name)))
    deps.add(path)
    # comments are gone from -E output: the first-party text carries the NOLINTs
    mine = [relative(d) + file_hash(d) for d in sorted(deps) if is_under(d, SRC)]
    return sha(relative(run.stdout.decode(errors="replace")), *mine), sorted(deps)


def preprocessed_hash(entry, path, command_key):
    manifest = os.path.join(CACHE, "manifest", command_key)
    try:
        with open(manifest) as f:
            known = json.load(f)
        if all(file_hash(expand(p)) == h for p, h in known["deps"].items()):
            return known["pp"]
    except (OSError, ValueError, KeyError):
        pass
    pp, deps = preprocess(entry, path)
    if pp is None:
        return None
    with open(manifest + ".tmp", "w") as f:
        json.dump({"pp": pp, "deps": {relative(d): file_hash(d) for d in deps}}, f)
    os.replace(manifest + ".tmp", manifest)
    return pp


def expand(p):
    return p.replace("<build>", BUILD).replace("<src>", SRC)


DIAGNOSTIC = re.compile(r"^(/[^:]+):(\d+):(\d+): (warning|error): (.*?)(?: \[([^\]]+)\])?$")


def diagnostics(output):
    """Blocks of (first line, check, text) for diagnostics in first-party files."""
    blocks, current = [], None
    for line in output.splitlines():
        m = DIAGNOSTIC.match(line)
        if m:
            current = None
            if first_party(os.path.normpath(m.group(1))):
                current = [relative(line), m.group(6) or "clang-diagnostic-" + m.group(4), [line]]
                blocks.append(current)
        elif current is not None and not re.match(r"^\d+ (warning|error)s? generated", line):
            current[2].append(line)
    return blocks


def check(path):
    entry = units[path]
    command = relative(" ".join(args_of(entry))) + "\n" + relative(entry["directory"])
    command_key = sha(config_key, " ".join(ANALYZER), relative(path), command)
    pp = preprocessed_hash(entry, path, command_key)
    key = sha(command_key, pp) if pp else None
    if key and os.path.exists(os.path.join(CACHE, "clean", key)):
        return path, True, []
    run = subprocess.run([TIDY, "-p", BUILD, "--quiet"]
                         + [f"--extra-arg={a}" for a in EXTRA + ANALYZER] + [path],
                         capture_output=True, text=True)
    found = diagnostics(run.stdout + "\n" + run.stderr)
    if run.returncode != 0 and not found:
        found = [[relative(path), "clang-tidy-failed",
                  [f"{path}: clang-tidy exited with {run.returncode}", run.stdout, run.stderr]]]
    if not found and key:
        open(os.path.join(CACHE, "clean", key), "w").close()
    return path, False, found


cached, seen, checks = 0, set(), Counter()
with concurrent.futures.ThreadPoolExecutor(JOBS) as pool:
    for path, hit, found in pool.map(check, sorted(units)):
        cached += hit
        for head, name, text in found:
            # a header's diagnostic comes once per TU that includes it: show it once
            if head not in seen:
                seen.add(head)
                checks[name] += 1
                print("\n".join(text), flush=True)

elapsed = time.monotonic() - start
cpu = os.times()
print(f"tidy: {len(units)} files, {cached} from cache, {elapsed:.0f} s "
      f"({cpu.children_user + cpu.children_system:.0f} s CPU)", end="")
if seen:
    print(f"; {len(seen)} diagnostics: "
          + ", ".join(f"{n} {c}" for c, n in checks.most_common()))
    sys.exit(1)
print("; no diagnostics")
PY
