#!/usr/bin/env python3
"""Mutation campaign over anisocert's own C++ (docs/mutation.md): who checks the checker.

A mutant changes one line of one source file the way real bugs do. The runner rebuilds
incrementally, runs the unit tests that cover the file's folder first and the whole suite (CTest)
only if they pass, and restores the file byte for byte. A mutant the tests fail on, or that hangs past
the timeout, is killed; one they pass on survived: either a hole in the tests or an equivalent
mutant (docs/mutation.md argues each). A mutant that does not compile is not counted.

  scripts/mutate [--count N] [--seed S] [--shard I/N] [--folders predicates,oracle,...]
                 [--headers] [--build DIR] [--report DIR] [--list]
  scripts/mutate --mutants FILE    the mutants listed in FILE, e.g. tests/mutation/holes.json

It needs a configured build folder (scripts/mutate runs scripts/build all first).

Selection is deterministic: every candidate of every folder is enumerated in a fixed order, each
operator's candidates are shuffled with the seed, and N/len(folders) mutants of each folder are
taken, the operators in turn. --shard I/N keeps the mutants whose index is I modulo N, so
machines split a campaign with no other coordination.
"""

import argparse
import dataclasses
import json
import os
import random
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

# The tests that cover a folder, run first: (test binary, GoogleTest filter) per folder, the
# longest folder that holds the file deciding; one process, stopping at the first failure. The
# whole suite (CTest) follows only if they pass, so this orders the work and changes no verdict.
FIRST_TESTS = {
    "predicates": ("unit_tests", "Metric*:NumberTypes*:Distortion*:FilteredVsExact*:BadInput*:ClassroomExamples*:AngleAgainstBound*:"
                   "Encroachment*:RadiusEdge*:SqrtSign*:DistortionEstimate*:LS_*:BWY_*:LU_*"),
    "oracle": ("unit_tests", "ConicIntersection*:AlgebraicPoints*:RealAlgebraic*:SharedLine*:Polynomial*:CertifiedRoots*:"
               "OracleDiagram*:SiteSet*:MeshCertifier*:MetricChecks*:CertifyFilterVsExact*:TriangulationCheck*:CliDiagram*:"
               "CliCertify*:CliDual*:Data/*"),
    "refiners": ("unit_tests", "StarRefiner*:StarSet*:SiteGrid*:Boundary.*:QuasiCocircular*:ExactSplit*:Polygon*:DelaunayInMetric*:"
                 "SegmentCells*:SplitPoint*:LsRefiner*:ExactTie*:VertexSubdivision*:DomainContainsBox*:DomainInterior*:"
                 "RefinementLoop*:CliMesh*:BackgroundMesh*:BackgroundCli*:Data/*"),
    "theory": ("unit_tests", "LS_*:BWY_*:LU_*:Cli.*"),
    "numbers": ("unit_tests", "Rational*:Excerpt*:Interval*:DecimalEnclosure*:FilterInterval*:Expansion*:RoundedQuotient*:"
                "ExactDouble*:NumberTypes*"),
    "fields": ("unit_tests", "BackgroundMesh*:BackgroundCli*:FieldsNormalized*:CliMesh*:Data/*"),
    "io/formats": ("format_tests", "*"),
}


def first_stage(file):
    """The FIRST_TESTS folder that decides for a source file (the longest that holds it), or None."""
    held = [f for f in FIRST_TESTS if file.startswith(f + "/")]
    return max(held, key=len) if held else None


# Tests of the build rather than of behaviour (the installed package, the include graph): a
# one-line change inside a function cannot fail them, and they take a third of the suite's time.
EXCLUDED = r"Api\.ConsumerBuildsAgainstInstalledPackage|LayerIncludes\."
# The cases per property of the whole suite's middle stage (Campaign.whole_suite).
QUICK_CASES = 100
# The survivors argued equivalent in docs/mutation.md, matched by file and line text.
EQUIVALENT = ROOT / "tests" / "mutation" / "equivalent.json"
# The binaries CTest runs (benchmarks are not built).
TARGETS = ["anisocert", "unit_tests", "property_tests", "format_tests", "cgal_tests", "peer_tests", "fuzz_support_tests"]


@dataclasses.dataclass
class Mutant:
    file: str
    line: int  # 1-based
    operator: str
    before: str
    after: str

    def diff(self):
        return f"--- {self.file}:{self.line}\n-{self.before}\n+{self.after}"


def mask(line, in_block):
    """The line with string and character literals and comments blanked, so operators are only
    found in code; and whether a block comment is still open at its end."""
    out, i, n = [], 0, len(line)
    while i < n:
        if in_block:
            j = line.find("*/", i)
            if j < 0:
                out.append(" " * (n - i))
                return "".join(out), True
            out.append(" " * (j + 2 - i))
            i, in_block = j + 2, False
        elif line.startswith("//", i):
            out.append(" " * (n - i))
            break
        elif line.startswith("/*", i):
            in_block = True
        elif line[i] in "\"'":  # the quotes stay, so an operator next to a literal is seen
            quote, j = line[i], i + 1
            while j < n and line[j] != quote:
                j += 2 if line[j] == "\\" else 1
            out.append(quote + " " * (min(j, n) - i - 1) + (quote if j < n else ""))
            i = j + 1
        else:
            out.append(line[i])
            i += 1
    return "".join(out), in_block


def stops_operand(code, i):
    """Whether the character at i ends an operand: a comma, a semicolon, ? or a lone : (not ::)."""
    c = code[i]
    if c == ":":
        return code[i - 1:i] != ":" and code[i + 1:i + 2] != ":"
    return c in ",;?"


def operand_end(code, start):
    """Where the operand that starts at `start` ends: at depth 0, before && or ||, a comma, a
    semicolon, an unmatched closing bracket, ? or :."""
    depth, i = 0, start
    while i < len(code):
        c = code[i]
        if c in "([{":
            depth += 1
        elif c in ")]}":
            if depth == 0:
                return i
            depth -= 1
        elif depth == 0 and (code.startswith(" && ", i) or code.startswith(" || ", i) or stops_operand(code, i)):
            return i
        i += 1
    return i


def operand_start(code, end):
    """Where the operand that ends at `end` (exclusive) starts, scanning backwards."""
    depth, i = 0, end - 1
    while i >= 0:
        c = code[i]
        if c in ")]}":
            depth += 1
        elif c in "([{":
            if depth == 0:
                return i + 1
            depth -= 1
        elif depth == 0 and (code[max(0, i - 3):i + 1] in (" && ", " || ") or stops_operand(code, i) or code.startswith("return ", i)
                             or (c == "=" and code[i - 1:i] not in "=<>!" and code[i + 1:i + 2] != "=")):
            return i + (7 if code.startswith("return ", i) else 1)
        i -= 1
    return 0


SWAPS = [(" < ", " <= ", "boundary"), (" <= ", " < ", "boundary"), (" > ", " >= ", "boundary"),
         (" >= ", " > ", "boundary"), (" == ", " != ", "negate"), (" != ", " == ", "negate"),
         (" + ", " - ", "arithmetic"), (" - ", " + ", "arithmetic"),
         ("Sign::positive", "Sign::negative", "sign"), ("Sign::negative", "Sign::positive", "sign"),
         (" && ", " || ", "logic"), (" || ", " && ", "logic")]
INTEGER = re.compile(r"(?<![\w.])(?<!e-)(?<!e\+)(\d+)(?![\w.])")
FLOATING = re.compile(r"(?<![\w.])(\d+\.\d*(?:e[-+]?\d+)?|\d+e[-+]?\d+)(?![\w.])")
CALL2 = re.compile(r"\b(\w+)\(([A-Za-z_][\w.]*), ([A-Za-z_][\w.]*)\)")
# Functions whose two arguments commute: swapping them is an equivalent mutant by construction.
SYMMETRIC = {"min", "max", "hull", "ordered", "gcd", "swap", "same_double"}
GUARD = re.compile(r"^(\s*)if \((.*)\) (return\b|continue;|break;|throw\b)")
SKIP = re.compile(r"^\s*(#|namespace\b|using\b|static_assert\b|template\b|//|\}?\s*$|case\b)")


def mutants_of_line(code, original):
    """Every mutant of one line: (operator, mutated line). `code` is the masked line."""
    found = []
    for old, new, op in SWAPS:
        for m in re.finditer(re.escape(old), code):
            if op == "arithmetic" and "\"" in code[m.start() - 1:m.end() + 1]:
                continue  # a string's concatenation: the mutant would not compile
            found.append((op, original[:m.start()] + new + original[m.end():]))
    for m in INTEGER.finditer(code):
        v = int(m.group(1))
        for new in sorted({v + 1, 2 * v} - {v}):
            found.append(("constant", original[:m.start()] + str(new) + original[m.end():]))
    for m in FLOATING.finditer(code):
        found.append(("constant", original[:m.start()] + "(2 * " + m.group(1) + ")" + original[m.end():]))
    for m in CALL2.finditer(code):
        if m.group(2) != m.group(3) and m.group(1) not in SYMMETRIC:
            found.append(("swap", original[:m.start(2)] + m.group(3) + ", " + m.group(2) + original[m.end(3):]))
    for m in re.finditer(r" (&&|\|\|) ", code):
        left = operand_start(code, m.start())
        right = operand_end(code, m.end())
        found.append(("drop-operand", original[:left] + original[m.end():]))  # keep the right operand
        found.append(("drop-operand", original[:m.start()] + original[right:]))  # keep the left
    g = GUARD.match(code)
    if g:
        cond = (g.start(2), g.end(2))
        found.append(("exit-always", original[:cond[0]] + "true" + original[cond[1]:]))
        found.append(("exit-never", original[:cond[0]] + "false" + original[cond[1]:]))
    return [(op, line) for op, line in found if line != original]


def candidates(folder, headers):
    exts = (".cpp", ".hpp") if headers else (".cpp",)
    out = []
    for path in sorted((ROOT / folder).rglob("*")):
        if path.suffix not in exts:
            continue
        rel = str(path.relative_to(ROOT))
        in_block = False
        for k, line in enumerate(path.read_text().split("\n"), start=1):
            code, in_block_after = mask(line, in_block)
            if not in_block and not SKIP.match(line):
                for op, after in mutants_of_line(code, line):
                    out.append(Mutant(rel, k, op, line, after))
            in_block = in_block_after
    return out


def select(folders, count, seed, headers):
    """count/len(folders) mutants of each folder, the operators taken in turn (each operator's
    candidates shuffled), so that no one operator fills the campaign."""
    chosen = []
    share = max(1, count // len(folders))
    for folder in folders:
        rng = random.Random(f"{seed}/{folder}")
        by_operator = {}
        for x in candidates(folder, headers):
            by_operator.setdefault(x.operator, []).append(x)
        queues = [by_operator[op] for op in sorted(by_operator)]
        for q in queues:
            rng.shuffle(q)
        rng.shuffle(queues)
        taken = []
        while len(taken) < share and any(queues):
            for q in queues:
                if q and len(taken) < share:
                    taken.append(q.pop())
        chosen.extend(taken)
    return chosen


def listed(path):
    """Mutants written by hand or kept from a campaign: [{"file", "before", "after"}], `before` a
    text that occurs on exactly one line of the file, or on several and then the one nearest to
    an optional "line"."""
    out = []
    for k, e in enumerate(json.loads(Path(path).read_text())):
        lines = (ROOT / e["file"]).read_text().split("\n")
        hits = [i for i, line in enumerate(lines) if e["before"] in line]
        if len(hits) > 1 and "line" in e:
            hits = [min(hits, key=lambda i: abs(i + 1 - e["line"]))]
        if len(hits) != 1:
            raise ValueError(f"{path}: mutant {k}: {e['before']!r} is on {len(hits)} lines of {e['file']}, not one")
        line = lines[hits[0]]
        out.append(Mutant(e["file"], hits[0] + 1, e.get("operator", "listed"), line, line.replace(e["before"], e["after"])))
    return out


def run(cmd, timeout, log, env=None):
    """Exit code, or None on timeout (the process group is killed)."""
    with open(log, "a") as out:
        out.write(f"$ {' '.join(cmd)}\n")
        out.flush()
        p = subprocess.Popen(cmd, cwd=ROOT, stdout=out, stderr=subprocess.STDOUT, start_new_session=True, env=env)
        try:
            return p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            return None
        finally:
            if p.poll() is None:  # timed out, or the campaign was interrupted
                os.killpg(p.pid, signal.SIGKILL)
                p.wait()


class Campaign:
    def __init__(self, a):
        self.build = ROOT / a.build
        self.report = ROOT / a.report
        self.report.mkdir(parents=True, exist_ok=True)
        self.log = self.report / "log.txt"
        self.jobs = str(os.cpu_count() or 2)
        self.backup = self.report / "original.json"  # the file under mutation, for a crash

    def restore_interrupted(self):
        if self.backup.exists():
            saved = json.loads(self.backup.read_text())
            (ROOT / saved["file"]).write_bytes(saved["text"].encode("latin-1"))
            self.backup.unlink()
            print(f"mutate: restored {saved['file']} from an interrupted run", file=sys.stderr)

    def configure(self):
        if not (self.build / "build.ninja").exists():
            subprocess.run(["cmake", "-S", str(ROOT), "-B", str(self.build), "-G", "Ninja", "-DANISOCERT_TESTS=ON",
                            "-DCMAKE_BUILD_TYPE=RelWithDebInfo", "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -DNDEBUG"],
                           check=True, stdout=subprocess.DEVNULL)

    def build_all(self, timeout):
        replay = [f"fuzz_replay_{h}" for h in fuzz_harnesses()]
        return run(["cmake", "--build", str(self.build), "-j", self.jobs, "--target", *TARGETS, *replay], timeout, self.log)

    def ctest(self, timeout, per_test, label_option=()):
        return run(["ctest", "--test-dir", str(self.build), "-j", self.jobs, "--stop-on-failure", "--timeout",
                    str(per_test), "-E", EXCLUDED, *label_option], timeout, self.log)

    def quick_properties(self, timeout):
        """Exit code of every property at QUICK_CASES cases, in one fail-fast process."""
        env = dict(os.environ, RC_PARAMS=f"max_success={QUICK_CASES}")
        with open(self.log, "a") as out:
            out.write(f"$ RC_PARAMS={env['RC_PARAMS']} property_tests --gtest_fail_fast\n")
        return run([str(self.build / "bin" / "property_tests"), "--gtest_fail_fast", "--gtest_brief=1"], timeout, self.log, env)

    def whole_suite(self, times):
        """The whole suite in three stages, each only if the ones before pass: every test but the
        properties, the properties at QUICK_CASES cases, the properties as CTest runs them (the
        suite's own cases). The first and last are the whole suite; the middle one finds most
        mutants the properties kill at a fifth of their cost. The stage that decided, and an exit
        code (None on timeout)."""
        budget = lambda k: 3 * times[k] + 120
        rc = self.ctest(budget("rest"), int(budget("rest")), ("-LE", "property"))
        if rc != 0:
            return "whole suite", rc
        rc = self.quick_properties(budget("quick"))
        if rc != 0:
            return f"properties at {QUICK_CASES} cases", rc
        return "properties", self.ctest(budget("properties"), int(budget("properties")), ("-L", "property"))

    def first_tests(self, folder, timeout):
        """Exit code of the tests that cover `folder`, or None on timeout."""
        binary, tests = FIRST_TESTS[folder]
        return run([str(self.build / "bin" / binary), f"--gtest_filter={tests}", "--gtest_fail_fast", "--gtest_brief=1"],
                   timeout, self.log)

    def verdict(self, m, suite_seconds, first_seconds):  # suite_seconds: per stage of whole_suite
        """killed, survived, timeout or stillborn, and the stage that decided."""
        path = ROOT / m.file
        original = path.read_bytes()
        self.backup.write_text(json.dumps({"file": m.file, "text": original.decode("latin-1")}))
        lines = original.decode().split("\n")
        if lines[m.line - 1] != m.before:  # a file left mutated by a killed run would make a no-op mutant
            self.backup.unlink()
            raise RuntimeError(f"{m.file}:{m.line} is not the line the mutant was made from: restore the sources first")
        lines[m.line - 1] = m.after
        path.write_text("\n".join(lines))
        try:
            if self.build_all(1800) != 0:
                return "stillborn", "build"
            folder = first_stage(m.file)
            if folder:
                rc = self.first_tests(folder, 3 * first_seconds[folder] + 60)
                if rc is None:
                    return "timeout", "first tests"
                if rc != 0:
                    return "killed", "first tests"
            stage, rc = self.whole_suite(suite_seconds)
            if rc is None:
                return "timeout", stage
            return ("killed", stage) if rc != 0 else ("survived", "")
        finally:
            path.write_bytes(original)  # byte for byte; its new mtime makes the next build redo it
            self.backup.unlink()


def fuzz_harnesses():
    return sorted(p.stem for p in (ROOT / "fuzz" / "harnesses").glob("*.cpp"))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--count", type=int, default=100, help="mutants, split evenly over the folders (default 100)")
    p.add_argument("--seed", default="2026", help="the selection's seed (default 2026)")
    p.add_argument("--shard", default="0/1", help="I/N: this machine's share of the campaign (default 0/1)")
    p.add_argument("--folders", default="predicates,numbers,oracle,theory,refiners/star,refiners/ls,refiners/bwy,refiners/common,"
                                        "fields,io/formats",
                   help="comma-separated source folders, each a share of --count (default: every folder that decides)")
    p.add_argument("--headers", action="store_true", help="mutate headers too (each rebuilds most of the project)")
    p.add_argument("--build", default="build", help="build folder, restored to the sources at the end (default build)")
    p.add_argument("--report", default="mutation-report", help="report folder (default mutation-report)")
    p.add_argument("--list", action="store_true", help="print the selected mutants and exit")
    p.add_argument("--mutants", help="run the mutants listed in this JSON file instead of a selection")
    a = p.parse_args()

    folders = [f for f in a.folders.split(",") if f]
    for f in folders:
        if not (ROOT / f).is_dir():
            print(f"mutate: --folders: no folder {f}", file=sys.stderr)
            return 2
    m = re.fullmatch(r"(\d+)/(\d+)", a.shard)
    if not m or int(m.group(2)) == 0 or int(m.group(1)) >= int(m.group(2)):
        print(f"mutate: --shard {a.shard}: expected I/N with 0 <= I < N", file=sys.stderr)
        return 2
    shard, shards = int(m.group(1)), int(m.group(2))
    c = Campaign(a)
    c.restore_interrupted()  # before the selection: it reads the sources
    try:
        chosen = listed(a.mutants) if a.mutants else select(folders, a.count, a.seed, a.headers)
    except (OSError, ValueError, KeyError) as e:
        print(f"mutate: {e}", file=sys.stderr)
        return 2
    mutants = [x for k, x in enumerate(chosen) if k % shards == shard]
    if a.list:
        for x in mutants:
            print(f"{x.operator:13} {x.diff()}")
        return 0

    def interrupted(signum, frame):  # restore the file under mutation (Campaign.verdict's finally)
        raise KeyboardInterrupt(f"signal {signum}")

    signal.signal(signal.SIGINT, interrupted)  # also when started in the background, where it is ignored
    signal.signal(signal.SIGTERM, interrupted)
    c.configure()
    print(f"mutate: building {c.build.name} and running the unmutated suite", file=sys.stderr)
    if c.build_all(7200) != 0:
        print(f"mutate: the unmutated project does not build (see {c.log})", file=sys.stderr)
        return 2
    suite = {}  # each stage of the whole suite, unmutated, for its own budget
    for stage, call in (("rest", lambda: c.ctest(7200, 1800, ("-LE", "property"))), ("quick", lambda: c.quick_properties(7200)),
                        ("properties", lambda: c.ctest(7200, 1800, ("-L", "property")))):
        start = time.monotonic()
        if call() != 0:
            print(f"mutate: the unmutated suite fails at {stage} (see {c.log}): fix it first", file=sys.stderr)
            return 2
        suite[stage] = time.monotonic() - start
    first = {}  # each first stage's unmutated time, for its own budget
    for folder in sorted({first_stage(x.file) for x in mutants} - {None}):
        start = time.monotonic()
        if c.first_tests(folder, 1800) != 0:
            print(f"mutate: the unmutated first tests of {folder} fail (see {c.log}): fix them first", file=sys.stderr)
            return 2
        first[folder] = time.monotonic() - start

    results = []
    began = time.monotonic()
    for k, x in enumerate(mutants, start=1):
        t0 = time.monotonic()
        verdict, stage = c.verdict(x, suite, first)
        seconds = round(time.monotonic() - t0, 1)
        results.append({**dataclasses.asdict(x), "verdict": verdict, "stage": stage, "seconds": seconds})
        print(f"mutate: [{k}/{len(mutants)}] {verdict:9} {x.file}:{x.line} {x.operator} ({seconds} s)", file=sys.stderr)
        (c.report / f"shard-{shard}-of-{shards}.json").write_text(json.dumps(results, indent=1))
    c.build_all(7200)  # the build folder matches the sources again
    write_summary(c.report, results, shard, shards, suite, time.monotonic() - began, argued_equivalent())
    return 0


def argued_equivalent():
    """The survivors tests/mutation/equivalent.json knows, by (file, before, after): their status
    ("equivalent", "outside the contract", "argued by a search") and second reader. Only an
    equivalent one that a second reader (who wrote neither the code nor the claim) tried to tell
    apart and could not is left out of the score (docs/mutation.md)."""
    listed = json.loads(EQUIVALENT.read_text())
    return {(e["file"], e["before"], e["after"]): e for e in listed}


def known(r, equivalent):
    return equivalent.get((r["file"], r["before"].strip(), r["after"].strip()))


def is_argued(r, equivalent):
    e = known(r, equivalent)
    return bool(e) and e.get("status") == "equivalent" and bool(e.get("second_reader"))


def write_summary(report, results, shard, shards, suite, seconds, equivalent):
    by_folder = {}
    for r in results:
        parts = r["file"].split("/")
        by_folder.setdefault("/".join(parts[:2]) if parts[0] in ("refiners", "io") and len(parts) > 2 else parts[0], []).append(r)
    out = [f"# Mutation campaign, shard {shard}/{shards}", "",
           f"{len(results)} mutants in {seconds / 60:.1f} min (unmutated suite: every test but the properties "
           f"{suite['rest']:.0f} s, the properties at {QUICK_CASES} cases {suite['quick']:.0f} s, at the suite's own "
           f"{suite['properties']:.0f} s).", "",
           "| folder | mutants | killed | timed out | survived | did not compile | score |", "|---|---|---|---|---|---|---|"]
    total = {"killed": 0, "timeout": 0, "survived": 0, "stillborn": 0}
    for folder, rs in sorted(by_folder.items()):
        n = {v: sum(r["verdict"] == v for r in rs) for v in total}
        for v in total:
            total[v] += n[v]
        counted = n["killed"] + n["timeout"] + n["survived"]
        score = f"{100 * (n['killed'] + n['timeout']) / counted:.0f}%" if counted else "—"
        out.append(f"| {folder} | {len(rs)} | {n['killed']} | {n['timeout']} | {n['survived']} | {n['stillborn']} | {score} |")
    counted = total["killed"] + total["timeout"] + total["survived"]
    score = f"{100 * (total['killed'] + total['timeout']) / counted:.1f}%" if counted else "—"
    out.append(f"| all | {len(results)} | {total['killed']} | {total['timeout']} | {total['survived']} | {total['stillborn']} | {score} |")
    argued = sum(r["verdict"] == "survived" and is_argued(r, equivalent) for r in results)
    if 0 < argued < counted:
        out += ["", f"Leaving out the {argued} survivors that are equivalent by docs/mutation.md, each checked by a second "
                f"reader (tests/mutation/equivalent.json): {total['killed'] + total['timeout']} / {counted - argued} = "
                f"{100 * (total['killed'] + total['timeout']) / (counted - argued):.1f}%."]
    out += ["", "## Survivors", ""]
    for r in results:
        if r["verdict"] == "survived":
            e = known(r, equivalent)
            tag = f" — {e['status']}" + ("" if e.get("second_reader") else ", no second reader yet") if e else ""
            out += [f"- `{r['file']}:{r['line']}` ({r['operator']}){tag}", "  ```diff", f"  -{r['before'].strip()}",
                    f"  +{r['after'].strip()}", "  ```"]
    (report / f"shard-{shard}-of-{shards}.md").write_text("\n".join(out) + "\n")
    print("\n".join(out[:out.index("## Survivors") - 1]))


if __name__ == "__main__":
    sys.exit(main())
