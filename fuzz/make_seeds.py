#!/usr/bin/python3
"""Writes the seed corpus of every fuzz target into fuzz/corpus/<target>/ (docs/reliability.md, "Fuzzing").

usage: fuzz/make_seeds.py BUILD_DIR      (BUILD_DIR/bin/rbcstab writes the journals, diagrams and branch files)

Seeds are the scenes of scenes/, outputs of small runs of the command line, and the hostile inputs the
reliability review tried (empty values, trailing text, repeated keys and modes, edited and spliced journal
records, out-of-range values). Every file is rewritten; corpus/<target>/regressions/ (inputs that once broke an
invariant) is left alone. The corpus stays small: the default suite replays all of it.
"""
import json
import pathlib
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
CORPUS = ROOT / "fuzz" / "corpus"


def fnv1a_hex(text: bytes) -> str:
    h = 14695981039346656037  # the FNV-1a 64 offset basis
    for c in text:
        h ^= c
        h = (h * 1099511628211) % (1 << 64)
    return f"{h:016x}"


class Writer:
    def __init__(self, target):
        self.dir = CORPUS / target
        self.dir.mkdir(parents=True, exist_ok=True)
        for f in self.dir.iterdir():
            if f.is_file():
                f.unlink()

    def put(self, name, content):
        data = content.encode() if isinstance(content, str) else content
        (self.dir / name).write_bytes(data)


def run(cli, *args, cwd):
    subprocess.run([str(cli), *args], cwd=cwd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def scene_seeds():
    w = Writer("scene_toml")
    for f in sorted((ROOT / "scenes").glob("*.toml")):
        w.put(f.name, f.read_bytes())
    w.put("every_key.toml", (ROOT / "fuzz" / "journal_scene.toml").read_text() + "\n[initial]\ndelta_l = { 3 = 2e-3, 7 = 1e-12 }\n"
          "rest_delta_l = { 4 = 1e-4 }\n[integrator]\nstepper = \"rosenbrock\"\nrtol = 1e-9\natol = 1e-13\nh_init = 1e-4\n"
          "h_min = 1e-14\nmax_steps = 123456\nmax_seconds = 30\n")
    hostile = {
        "empty.toml": "",
        "nan_lambda.toml": "[parameters]\nlambda = nan\n",
        "inf_T.toml": "[run]\nT = inf\n",
        "huge_dt.toml": "[run]\nT = 5.0\ndt = 500.0\n",
        "beta_out_of_range.toml": "[initial]\nbeta = 4.0\n",
        "negative_beta.toml": "[initial]\nbeta = -1.0\n",
        "L_as_float.toml": "[run]\nL = 4.0\n",
        "L_huge.toml": "[run]\nL = 9223372036854775807\n",
        "mode_key_text.toml": "[initial]\ndelta_l = { x = 1e-3 }\n",
        "mode_key_float.toml": "[initial]\ndelta_l = { \"3.5\" = 1e-3 }\n",
        "mode_key_padded.toml": "[initial]\ndelta_l = { 3 = 1e-3, \"03\" = 2e-3 }\n",
        "mode_key_spaced.toml": "[initial]\ndelta_l = { 3 = 1e-3, \" 3\" = 2e-3 }\n",
        "mode_key_plus.toml": "[initial]\ndelta_l = { \"+3\" = 1e-3 }\n",
        "modes_as_array.toml": "[initial]\ndelta_l = [1e-3]\n",
        "repeated_key.toml": "[parameters]\nB = 1.0\nB = 2.0\n",
        "repeated_table.toml": "[run]\nT = 5.0\n[run]\nT = 6.0\n",
        "unknown_key.toml": "[parameters]\nBB = 1.0\n",
        "unknown_table.toml": "[banana]\nx = 1\n",
        "table_as_value.toml": "parameters = 3\n",
        "name_multiline.toml": "name = \"\"\"a\nb \\\" c\"\"\"\n",
        "name_unicode.toml": "name = \"\\u00e9\\u0000\"\n",
        "two_panels.toml": "[diagram]\ncounts = [2, 2]\n[fig6e]\nB = [1.0]\n",
        "diagram_counts_huge.toml": "[diagram]\ncounts = [1000000, 1000000]\n",
        "diagram_counts_zero.toml": "[diagram]\ncounts = [0, 3]\n",
        "diagram_same_axes.toml": "[diagram]\naxes = [\"lnB\", \"lnB\"]\n",
        "diagram_range_overflow.toml": "[diagram]\nx_range = [-1e308, 1e308]\n",
        "diagram_alpha_negative.toml": "[diagram]\nalpha = -1.0\n",
        "continuation_panel.toml": "[continuation]\nparameter = \"lambda\"\nmin = 0.5\nmax = 5.0\ndirection = \"both\"\n",
        "continuation_bad_direction.toml": "[continuation]\ndirection = \"sideways\"\n",
        "fig6e_panel.toml": "[fig6e]\nlambda = [1.0, 5.0]\nB = [1.0, 2.0]\nC = [0.01]\n",
        "fig6e_empty_array.toml": "[fig6e]\nB = []\n",
        "integrator_bad.toml": "[integrator]\nrtol = 0.0\natol = -1.0\nmax_steps = 0\n",
        "syntax_error.toml": "[parameters]\nB = = 2\n",
        "deep_nesting.toml": "x = " + "[" * 64 + "]" * 64 + "\n",
    }
    for name, text in hostile.items():
        w.put(name, text)


def mode_seeds():
    w = Writer("mode_list")
    cases = ["3=1e-3", "3=1e-3,4=2e-3", "3=0.05\n4=0.07", "7=1e-12", "3=0", "3=0x1p-10",
             # the review's cases: only the first mode, trailing text, a second '=', a non-integer mode
             "3=0.05,4=0.07", "3=0.1abc", "3=0.1=2", "3.5=0.1", "", "3=", "=1", "3=1e-3,", ",3=1e-3", "3=1,3=2",
             "3=1\n3=2", " 3=1e-3", "3= 1e-3", "3=1e-3 ", "+3=1e-3", "-3=1e-3", "2=1e-3", "101=1e-3",
             "3=nan", "3=inf", "3=-1e-3", "3=1e400", "99999999999=1", "3=1e-3,,4=1e-3"]
    for k, text in enumerate(cases):
        w.put(f"case{k:02d}", text)


def cli_list_seeds():
    w = Writer("cli_lists")
    shards = ["0/1", "3/4", "1/2", "4/4", "-1/4", "1/0", "1/-2", "0/", "/4", "1/2/3", "1.5/4", "01/4", " 1/4", "1/4 ",
              "+1/4", "1/2abc", "", "99999999999/99999999999"]
    measures = ["r,Psi,sigma", "sigma", "", "r,,Psi", ",r", "r,", "nope", "r,r", "Delta_3", " r"]
    axes = ["lnB", "lnC", "lambda", "LNB", "lnB ", "ln B", "", "beta"]
    classifiers = ["auto", "final", "tail", "Final", "tail ", ""]
    for kind, values in enumerate([shards, measures, axes, classifiers]):
        for k, v in enumerate(values):
            w.put(f"kind{kind}_{k:02d}", bytes([kind]) + v.encode())


def cli_arg_seeds():
    w = Writer("cli_args")
    cases = [
        ["diagram", "--x-range=-1,6", "--y-range=-5.5,2", "--counts", "4,4", "--axes", "lnB,lnC"],
        ["diagram", "--x-range", "1,,2", "--counts", "16,16"],
        ["diagram", "--counts", "16,,16"], ["diagram", "--counts", "010,4"], ["diagram", "--counts", "0x10,4"],
        ["diagram", "--counts", "1000000,1000000"], ["diagram", "--x-range=-1e308,1e308"], ["diagram", "--out", ""],
        ["diagram", "--shard", "1/4", "--threads", "2"], ["diagram", "--axes", "lnB,,lnC"],
        ["trace", "--x-range", "1", "2", "--y-range", "0,1"], ["trace", "--threads", "-1"], ["trace", "--threads", "4097"],
        ["trace", "--horizon", "-1"], ["simulate", "--lambda", ""], ["simulate", "--lambda", "abc"],
        ["simulate", "--lambda", "1e308"], ["simulate", "--L", "010"], ["simulate", "--L", ""], ["simulate", "--L", "3.5"],
        ["simulate", "--delta-l", "3=0.05,4=0.07"], ["simulate", "--delta-l", "3=0.1abc"], ["simulate", "--lambda", "2", "--lambda", "3"],
        ["continue", "--parameter", "beta", "--min", "-1", "--max", "4"], ["continue", "--min", ""], ["continue", "--max-points", "-1"],
        ["continue", "--measures", "r,,Psi"], ["continue", "--step", "1e308"], ["thresholds", "--lambda", "1e308", "--json"],
        ["thresholds", "--C", "inf"], ["report", "--T", "5", "--no-reduced", "--output", "X"], ["merge", "a.json", "b.json"],
        ["summary", "--beta", "4"], ["--version"], ["--help"], [],
    ]
    for k, args in enumerate(cases):
        w.put(f"case{k:02d}", "\n".join(args))


def journal_seeds(work, cli):
    w = Writer("journal")
    scene = ROOT / "fuzz" / "journal_scene.toml"
    run(cli, "diagram", "--scene", str(scene), "--out", "j", "--quiet", cwd=work)
    text = (work / "j.journal").read_bytes()
    lines = text.splitlines(keepends=True)
    header, records = lines[0], lines[1:]

    def fields(line):
        body = line.rstrip(b"\n").rsplit(b" *", 1)[0]
        return body.split(b" |")[0].split(b" "), body.split(b" |", 1)[1]

    def record(f, reason):
        body = b" ".join(f) + b" |" + reason
        return body + b" *" + fnv1a_hex(body).encode() + b"\n"

    def edited(k, field, value):  # record k with one field changed and a valid checksum
        f, reason = fields(records[k])
        f[field] = value
        return record(f, reason)

    as_given, fixed = b"\x00", b"\x01"  # the target's first byte: write as given, or recompute checksums
    w.put("complete", as_given + text)
    w.put("header_only", as_given + header)
    w.put("empty", as_given)
    w.put("torn_header", as_given + header[:20])
    w.put("partial", as_given + header + records[0] + records[3])
    w.put("torn_last_record", as_given + header + records[0] + records[1][:30])
    w.put("flipped_verdict_no_checksum", as_given + header + records[0].replace(b"unstable", b"stable ") + records[1])
    w.put("flipped_verdict", fixed + header + records[0].replace(b" unstable ", b" stable "))
    w.put("l_delta_beyond_L", as_given + header + edited(0, 4, b"7"))
    w.put("l_delta_negative", as_given + header + edited(0, 4, b"-7"))
    w.put("growth_nan", as_given + header + edited(0, 5, b"nan"))
    w.put("growth_dash", as_given + header + edited(0, 5, b"-"))
    w.put("index_swapped", as_given + header + edited(0, 2, b"1") + edited(1, 2, b"0") + records[2])
    w.put("index_outside", as_given + header + edited(0, 2, b"4"))
    w.put("index_huge", as_given + header + edited(0, 2, b"18446744073709551616"))
    w.put("duplicated", as_given + header + records[0] + records[0] + records[1])
    w.put("foreign_hash", as_given + header + edited(0, 1, b"0123456789abcdef"))
    w.put("verdict_banana", as_given + header + edited(0, 3, b"banana"))
    w.put("status_unknown", as_given + header + edited(0, 8, b"exploded"))
    w.put("seconds_negative", as_given + header + edited(0, 13, b"-1"))
    w.put("oscillating_2", as_given + header + edited(0, 6, b"2"))
    w.put("failed_point", fixed + header + edited(3, 8, b"step_limit").replace(b" stable ", b" failed ")
          .replace(b"|", b"|max_steps reached"))
    w.put("spliced", as_given + header + records[0][:40] + b"P " + records[1][2:] + records[2])
    w.put("crlf", as_given + header.replace(b"\n", b"\r\n") + records[0])
    w.put("old_format", as_given + header.replace(b" v2 ", b" v1 ") + records[0])
    w.put("foreign_header", as_given + header.replace(header[-5:-1], b"beef") + records[0])
    w.put("no_newline_at_end", as_given + header + records[0].rstrip(b"\n"))


def merge_seeds(work, cli):
    w = Writer("merge")
    scene = ROOT / "fuzz" / "journal_scene.toml"
    run(cli, "diagram", "--scene", str(scene), "--out", "m", "--quiet", "--no-journal", "--counts", "2,1", cwd=work)
    for k in range(2):
        run(cli, "diagram", "--scene", str(scene), "--out", "s", "--quiet", "--no-journal", "--counts", "2,1",
            "--shard", f"{k}/2", "--no-seconds", cwd=work)
    full = json.loads((work / "m.json").read_text())
    full.pop("agreement", None)  # the merge recomputes it; it is the bulk of the file
    s0 = json.loads((work / "s.shard0of2.json").read_text())
    s1 = json.loads((work / "s.shard1of2.json").read_text())
    dump = lambda d: json.dumps(d, indent=1)
    w.put("complete.json", dump(full))
    w.put("two_shards", dump(s0) + "\n----\n" + dump(s1))
    w.put("one_shard", dump(s0))
    w.put("same_shard_twice", dump(s0) + "\n----\n" + dump(s0))

    def edited(doc, change):
        d = json.loads(json.dumps(doc))
        change(d)
        return dump(d)

    def point(key, value):
        return lambda d: d["points"][0].__setitem__(key, value)

    w.put("l_delta_negative", edited(s0, point("l_Delta", -7)))
    w.put("l_delta_beyond_L", edited(s0, point("l_Delta", 99)))
    w.put("verdict_banana", edited(s0, point("verdict", "banana")))
    w.put("growth_null", edited(s0, point("growth", None)))
    w.put("growth_text", edited(s0, point("growth", "nan")))
    w.put("index_outside", edited(s0, point("index", 7)))
    w.put("index_negative", edited(s0, point("index", -1)))
    w.put("index_float", edited(s0, point("index", 0.5)))
    w.put("steps_huge", edited(s0, point("steps", 18446744073709551615)))
    w.put("oscillating_number", edited(s0, point("oscillating", 1)))
    w.put("points_not_array", edited(s0, lambda d: d.__setitem__("points", {})))
    w.put("point_not_object", edited(s0, lambda d: d["points"].__setitem__(0, 3)))
    w.put("hash_number", edited(s0, lambda d: d.__setitem__("config_hash", 12)))
    w.put("seconds_included_text", edited(s0, lambda d: d.__setitem__("seconds_included", "yes")))
    w.put("no_scene", edited(s0, lambda d: d.pop("scene_toml")))
    w.put("scene_invalid", edited(s0, lambda d: d.__setitem__("scene_toml", "[run]\nL = 1\n")))
    w.put("other_hash", dump(s0) + "\n----\n" + edited(s1, lambda d: d.__setitem__("config_hash", "0" * 16)))
    w.put("disagreeing_points", dump(s0) + "\n----\n" + edited(s0, point("l_Delta", 3)))
    w.put("counts_zero", edited(s0, lambda d: d["diagram"]["x"].__setitem__("count", 0)))
    w.put("format_other", edited(s0, lambda d: d.__setitem__("format", "rbcstab-trace")))
    w.put("not_json", "{\"format\": \"rbcstab-diagram\", ")
    w.put("array", "[1, 2, 3]")


def branch_seeds(work, cli):
    w = Writer("branch_file")
    modal = ["continue", "--kind", "modal", "--parameter", "C", "--min", "0.015", "--max", "0.08", "--direction",
             "backward", "--lambda", "1", "--B", "1", "--L", "4"]
    run(cli, *modal, "--save", "modal.json", cwd=work)
    run(cli, *modal, "--switch-at-bp", "--save", "switch.json", cwd=work)
    run(cli, *modal, "--curve", "BP", "--parameter2", "B", "--min2", "0.8", "--max2", "1.2", "--max-points", "20",
        "--save", "curve.json", cwd=work)
    run(cli, *modal, "--monitor", "C=0.05,0.04", "--stop-at", "C=0.03", "--save", "monitors.json", cwd=work)
    run(cli, "continue", "--max-points", "8", "--save", "equilibrium.json", cwd=work)
    run(cli, "continue", "--kind", "orbit", "--max-points", "4", "--save", "orbit.json", cwd=work)
    docs = {}
    for name in ["modal", "switch", "curve", "equilibrium", "orbit", "monitors"]:
        text = (work / f"{name}.json").read_text()
        docs[name] = json.loads(text)
        w.put(f"{name}.json", text)

    def edited(name, change):
        d = json.loads(json.dumps(docs[name]))
        change(d)
        return json.dumps(d, indent=1)

    def first_point(key, value):
        return lambda d: d["branch"][0].__setitem__(key, value)

    w.put("truncated.json", json.dumps(docs["equilibrium"])[:3000])
    w.put("version_2.json", edited("equilibrium", lambda d: d.__setitem__("version", 2)))
    w.put("no_format.json", edited("equilibrium", lambda d: d.pop("format")))
    w.put("label_twice.json", edited("equilibrium", lambda d: d["branch"][1].__setitem__("label", d["branch"][0]["label"])))
    w.put("label_zero.json", edited("equilibrium", first_point("label", 0)))
    w.put("state_short.json", edited("equilibrium", first_point("x", [0.5])))
    w.put("state_nan.json", edited("equilibrium", first_point("x", None)))
    w.put("p_text.json", edited("equilibrium", first_point("p", "1")))
    w.put("winding_overflow.json", edited("orbit", first_point("winding", 4294967297)))
    w.put("winding_float.json", edited("orbit", first_point("winding", 1.5)))
    w.put("kind_unknown.json", edited("orbit", first_point("kind", "banana")))
    w.put("spec_scene_invalid.json", edited("equilibrium", lambda d: d["spec"].__setitem__("scene", "[run]\nL = 1\n")))
    w.put("engine_negative_step.json", edited("equilibrium", lambda d: d["spec"]["engine"].__setitem__("max_step", -1)))
    w.put("direction_unknown.json", edited("equilibrium", lambda d: d["spec"]["engine"].__setitem__("direction", "up")))
    w.put("monitor_malformed.json", edited("monitors", lambda d: d["spec"].__setitem__("monitor", ["C"])))
    w.put("monitor_not_text.json", edited("monitors", lambda d: d["spec"].__setitem__("stop_at", [0.03])))
    w.put("monitor_unknown.json", edited("monitors", lambda d: d["spec"].__setitem__("monitor", ["nope=1"])))
    w.put("special_after_last.json", edited("modal", lambda d: d["special_points"][0].__setitem__("after_index", 10**6)
                                            if d["special_points"] else None))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    cli = pathlib.Path(sys.argv[1]).resolve() / "bin" / "rbcstab"
    scene_seeds()
    mode_seeds()
    cli_list_seeds()
    cli_arg_seeds()
    work = pathlib.Path(tempfile.mkdtemp(prefix="rbcstab-seeds-"))
    try:
        journal_seeds(work, cli)
        merge_seeds(work, cli)
        branch_seeds(work, cli)
    finally:
        shutil.rmtree(work)
    total = sum(f.stat().st_size for f in CORPUS.rglob("*") if f.is_file())
    print(f"fuzz/make_seeds.py: {sum(1 for f in CORPUS.rglob('*') if f.is_file())} files, {total} bytes")


if __name__ == "__main__":
    main()
