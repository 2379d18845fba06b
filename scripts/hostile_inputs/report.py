#!/usr/bin/env python3
"""Reads OUTDIR/raw.tsv written by run.sh, checks every output with check_mesh.py,
classifies each run and writes the Markdown table.

  report.py OUTDIR RESULTS.md|- BIN

Problems (a run can have several):
  CRASH      exit code other than 0 and 2 (or a signal), not a timeout
  HANG       killed by the timeout
  BALLOON    peak RSS above 2 GB
  WRONG      exit 0 with a missing or invalid output: unreadable, not 2-manifold or
             inconsistently oriented, open although the input was closed (STL: the
             merged triangle set), colours not following the input's, different
             from the reference case, --stats not valid JSON
  OUT-ON-2   exit 2 but the output file was created (or a temporary file left)
  REFUSED    exit 2 on a usable mesh (expect=accept, or auto and the input is a
             readable mesh whose edges have <= 2 faces and that is orientable)
  ACCEPTED   exit 0 on an input that must be refused (NaN, missing vertex, ...)
  STDERR     exit 2 without exactly one line on stderr
  INPUT      the input file was modified by a failed run
"""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from check_mesh import check, read_mesh, merge_points, analyse, ParseError  # noqa: E402

BALLOON_KB = 2 * 1024 * 1024


def input_verdict(path, cache={}):
    """(usable, closed, note) of an input file, judged independently."""
    if path in cache:
        return cache[path]
    try:
        pts, faces, cols = read_mesh(path)
        pts, faces = merge_points(pts, faces)  # usable after the usual repair (merge)
        a = analyse(pts, faces, cols, True)
        usable = (a["faces"] > 0 and a["finite"] and a["indices_in_range"] and a["short_faces"] == 0
                  and a["non_manifold_edges"] == 0 and a["orientable"])
        bits = []
        if a["non_manifold_vertices"]:
            bits.append("%d nm-vertices" % a["non_manifold_vertices"])
        if a["misoriented_edges"]:
            bits.append("%d misoriented edges" % a["misoriented_edges"])
        if a["non_manifold_edges"]:
            bits.append("%d nm-edges" % a["non_manifold_edges"])
        if a["repeated_index_faces"]:
            bits.append("%d faces repeating a vertex" % a["repeated_index_faces"])
        if not a["orientable"]:
            bits.append("not orientable")
        if a["components"] > 1:
            bits.append("%d components" % a["components"])
        if not a["closed"]:
            bits.append("%d border edges" % a["border_edges"])
        # few repeated-index faces are dropped by any repair: still usable
        r = (usable, a["closed"] and usable and a["non_manifold_vertices"] == 0, ", ".join(bits))
    except Exception as e:  # noqa: BLE001 - any failure means: not judged usable
        r = (False, False, "unreadable by check_mesh (%s)" % str(e)[:60])
    cache[path] = r
    return r


def main():
    outdir, results, binary = sys.argv[1], sys.argv[2], sys.argv[3]
    rows = []
    with open(os.path.join(outdir, "raw.tsv"), encoding="utf-8", errors="replace") as fh:
        header = fh.readline().rstrip("\n").split("\t")
        for line in fh:
            vals = line.rstrip("\n").split("\t")
            vals += [""] * (len(header) - len(vals))
            rows.append(dict(zip(header, vals)))
    by_key = {}
    for r in rows:
        for col, suffix in (("input", "inpath"), ("output", "outpath")):
            side = os.path.join(outdir, "log", r["key"] + "." + suffix)
            if os.path.exists(side):
                with open(side, encoding="utf-8", errors="surrogateescape") as fh:
                    r[col] = fh.read()
        flags = [] if r["flags"] in ("-", "") else r["flags"].split(",")
        r["flags_list"] = flags
        rc = int(r["rc"]) if r["rc"].lstrip("-").isdigit() else -1
        r["rc_int"] = rc
        secs = float(r["seconds"] or 0)
        rss = int(r["rss_kb"] or 0)
        probs = []
        why = []
        expect = r["expect"]
        inp = r["input"]
        closed_expected = "closed" in flags
        if expect == "auto":
            usable, closed, note = input_verdict(inp)
            expect = "accept" if usable else "any"
            closed_expected = closed
            r["input_note"] = note
        else:
            r["input_note"] = ""
        r["expect_eff"] = expect
        timed_out = rc == 124 or (rc in (137, 143) and secs >= 100)
        if timed_out:
            probs.append("HANG")
        elif rc not in (0, 2):
            probs.append("CRASH")
            why.append("exit %d%s" % (rc, " (signal %d)" % (rc - 128) if rc > 128 else ""))
        if rss > BALLOON_KB:
            probs.append("BALLOON")
        out = r["output"]
        valid = "-"
        if rc == 0:
            if r["output_exists"] != "yes":
                probs.append("WRONG")
                why.append("no output file")
                valid = "missing"
            elif os.path.getsize(out) > 150e6:
                valid = "not checked (%.0f MB file)" % (os.path.getsize(out) / 1e6)
            else:
                res = check(out, expect_closed=closed_expected,
                            color_fn="colorfn" in flags and out.lower().rsplit(".", 1)[-1] in ("ply", "off"))
                r["check"] = res
                if res.get("valid"):
                    valid = "yes (%dv %df%s)" % (res["vertices"], res["faces"], ", closed" if res.get("closed") else "")
                else:
                    valid = "NO: " + res.get("why", "?")
                    probs.append("WRONG")
                    why.append(res.get("why", "?"))
            if r["mode"] == "stats" and r["stats_json"] == "invalid":
                probs.append("WRONG")
                why.append("--stats output is not valid JSON")
            if expect == "refuse":
                probs.append("ACCEPTED")
        elif rc == 2:
            if r["output_exists"] == "yes" and "same" not in flags:
                probs.append("OUT-ON-2")
                why.append("output created on failure")
            if expect == "accept":
                probs.append("REFUSED")
            if int(r["stderr_lines"] or 0) != 1:
                probs.append("STDERR")
                why.append("%s stderr lines" % r["stderr_lines"])
            if r["input_changed"] == "yes":
                probs.append("INPUT")
                why.append("input modified")
        if r["leftover_tmp"] == "yes":
            probs.append("OUT-ON-2" if rc != 0 else "WRONG")
            why.append("temporary file left behind")
        r["probs"] = probs
        r["why"] = why
        r["valid"] = valid
        by_key[(r["id"].split("/")[-1], r["id"].split("/")[0], r["mode"])] = r
    # same_as: compare with the reference case's output (same directory and mode)
    for r in rows:
        for f in r["flags_list"]:
            if f.startswith("same_as="):
                ref = by_key.get((f.split("=", 1)[1], r["id"].split("/")[0], r["mode"]))
                if ref and "check" in r and "check" in ref:
                    a, b = r["check"], ref["check"]
                    if (a.get("vertices"), a.get("faces")) != (b.get("vertices"), b.get("faces")) or \
                            abs(a.get("area", 0) - b.get("area", 0)) > 1e-9 * max(1.0, abs(b.get("area", 0))):
                        r["probs"].append("WRONG")
                        r["why"].append("differs from %s (%sv %sf area %.6g vs %sv %sf area %.6g)" % (
                            ref["id"], a.get("vertices"), a.get("faces"), a.get("area", 0),
                            b.get("vertices"), b.get("faces"), b.get("area", 0)))
                elif ref and (ref["rc_int"] == 0) != (r["rc_int"] == 0):
                    r["probs"].append("WRONG")
                    r["why"].append("exit %d where %s exits %d" % (r["rc_int"], ref["id"], ref["rc_int"]))

    cats = ["CRASH", "HANG", "BALLOON", "WRONG", "OUT-ON-2", "REFUSED", "ACCEPTED", "STDERR", "INPUT"]
    count = {c: 0 for c in cats}
    files_with = {c: set() for c in cats}
    for r in rows:
        for c in set(r["probs"]):
            count[c] += 1
            files_with[c].add(r["id"])
    cases = sorted(set(r["id"] for r in rows))
    lines = []
    lines.append("# range_space_remesh hostile corpus: results\n")
    lines.append("Binary: `%s`; outputs and logs: `%s`. %d cases, %d runs (each file: default options "
                 "with output in its own format, and `--stats` with output in another format), timeout %s s, "
                 "address space capped at 8 GB.\n" % (binary, outdir, len(cases), len(rows), os.environ.get("TIMEOUT", "120")))
    lines.append("## Summary\n")
    lines.append("| problem | runs | cases |")
    lines.append("|---|---:|---:|")
    desc = {
        "CRASH": "crash (exit not 0/2, or a signal)",
        "HANG": "hang (timeout)",
        "BALLOON": "peak memory > 2 GB",
        "WRONG": "exit 0 with a missing/invalid/wrong output (incl. invalid --stats JSON)",
        "OUT-ON-2": "exit 2 with the output (or a temp file) created",
        "REFUSED": "refused (exit 2) although usable",
        "ACCEPTED": "accepted (exit 0) although it must be refused",
        "STDERR": "exit 2 without exactly one stderr line",
        "INPUT": "input modified by a failed run",
    }
    for c in cats:
        lines.append("| %s | %d | %d |" % (desc[c], count[c], len(files_with[c])))
    ok = sum(1 for r in rows if not r["probs"])
    lines.append("| runs without any problem | %d | |" % ok)
    rc0 = sum(1 for r in rows if r["rc_int"] == 0)
    rc2 = sum(1 for r in rows if r["rc_int"] == 2)
    lines.append("\nExit 0: %d runs, exit 2: %d runs, other: %d. Peak RSS max %.0f MB; slowest run %.1f s.\n" % (
        rc0, rc2, len(rows) - rc0 - rc2,
        max(int(r["rss_kb"] or 0) for r in rows) / 1024.0, max(float(r["seconds"] or 0) for r in rows)))
    lines.append("## Cases with problems\n")
    for c in cats:
        if files_with[c]:
            lines.append("- **%s** (%d): %s" % (c, len(files_with[c]), ", ".join("`%s`" % x.replace("\n", "\\n") for x in sorted(files_with[c]))))
    lines.append("\n## All runs\n")
    lines.append("| case | mode | expect | exit | stderr (first line) | RSS MB | s | output valid | problems |")
    lines.append("|---|---|---|---:|---|---:|---:|---|---|")
    esc = lambda s: s.replace("|", "\\|").replace("\n", "\\n")
    for r in rows:
        exp = r["expect_eff"] + (" (%s)" % r["input_note"] if r.get("input_note") else "")
        prob = ", ".join(r["probs"]) + (": " + "; ".join(r["why"]) if r["why"] else "")
        lines.append("| %s | %s | %s | %s | %s | %.0f | %s | %s | %s |" % (
            esc(r["id"]), r["mode"], esc(exp), r["rc"], esc(r["stderr_first"][:160]),
            int(r["rss_kb"] or 0) / 1024.0, r["seconds"], esc(r["valid"]), esc(prob) or "ok"))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(outdir, "RESULTS.md"), "w") as fh:
        fh.write(text)
    if results != "-":
        with open(results, "w") as fh:
            fh.write(text)
    # short summary on stdout
    print("\n".join(lines[:lines.index("## All runs\n")] if "## All runs\n" in lines else lines[:30]))


if __name__ == "__main__":
    main()
