"""The doc test's own test: its parser, its output rule and its verdicts on small documents whose
right answer is known (a passing block, a stale figure, a broken command, an expected failure
that passes, a skip), run against a build directory made for the purpose."""

import contextlib
import io
import os
import shutil
import tempfile

import doc_test

FAILURES = []


def check(condition, what):
    if not condition:
        FAILURES.append(what)


def check_parser():
    blocks = doc_test.parse_blocks(
        "text\n<!-- doc-test: skip (installs packages) -->\n```sh\napt-get install x\n```\n"
        "<!-- doc-test: replace \"--racks 20\" \"--racks 1\" (time) -->\n"
        "<!-- doc-test: timeout 90 -->\n```bash\nrun --racks 20\n```\n\n```json\n{}\n```\n")
    check(len(blocks) == 3, "three fenced blocks")
    check(blocks[0].skip == "installs packages", "a skip's reason")
    check(blocks[1].script_text() == "run --racks 1\n", "a replacement made")
    check(blocks[1].timeout == 90, "a timeout read")
    check(not blocks[2].is_command(), "json is not run")
    for bad in ("<!-- doc-test: skip -->\n```sh\nx\n```\n",            # no reason
                "<!-- doc-test: frobnicate -->\n```sh\nx\n```\n",      # unknown
                "```\nbuild/bin/billiard\n```\n"):                     # no language
        with contextlib.suppress(doc_test.DocError):
            doc_test.parse_blocks(bad)
            check(False, f"refused: {bad!r}")
    stale = doc_test.parse_blocks("<!-- doc-test: replace \"a\" \"b\" (x) -->\n```sh\nc\n```\n")
    with contextlib.suppress(doc_test.DocError):
        stale[0].script_text()
        check(False, "a replacement that no longer applies is refused")


def check_output_rule():
    match = doc_test.output_matches
    check(match(['{"t":9.27439,"n":52,"us":..}'], ['{"t":9.274391,"n":52,"us":237.1}']),
          "numbers to the quoted digits, .. for a timing")
    check(not match(['{"n":52}'], ['{"n":51}']), "a stale integer")
    check(not match(["error 35.4 mm"], ["error 35.46 mm"]), "35.46 does not round to 35.4")
    check(match(["a  b", "...", "z 1.5e-10"], ["a b", "x", "y", "z 1.54e-10"]),
          "spaces, an elided run of lines, exponents")
    check(not match(["a", "b"], ["a", "b", "c"]), "an extra line")
    check(doc_test.console_commands("$ x \\\n  --y\nout\n$ z\n") ==
          [("x \\\n  --y", ["out"]), ("z", [])], "console commands and their output")


DOCUMENT = """
```sh
hello > greeting.txt && cat greeting.txt
false   # exit 1
```
<!-- doc-test: output -->
```text
hello from build/bin, 0.25 s
```
```console
$ hello
hello from build/bin, .. s
```
<!-- doc-test: skip (a camera) -->
```sh
false
```
"""


def run_document(text, source, build):
    with open(os.path.join(source, "docs", "d.md"), "w") as f:
        f.write(text)
    with contextlib.redirect_stdout(io.StringIO()) as printed:
        ok = doc_test.run_file(os.path.join(source, "docs", "d.md"), source, build, None)
    return ok, printed.getvalue()


def check_verdicts():
    top = tempfile.mkdtemp(prefix="doc_selftest_")
    source, build = os.path.join(top, "source"), os.path.join(top, "build")
    os.makedirs(os.path.join(source, "docs"))
    os.makedirs(os.path.join(build, "bin"))
    hello = os.path.join(build, "bin", "hello")
    with open(hello, "w") as f:
        f.write("#!/bin/sh\necho 'hello from build/bin, 0.25 s'\n")
    os.chmod(hello, 0o755)
    try:
        ok, printed = run_document(DOCUMENT, source, build)
        check(ok, "a document that runs passes:\n" + printed)
        check("2 run, 2 compared, 1 skipped" in printed, "the counts:\n" + printed)
        check(not os.path.exists(os.path.join(source, "greeting.txt")), "the tree left alone")
        for broken in (DOCUMENT.replace("0.25 s", "0.5 s", 1),       # a stale figure
                       DOCUMENT.replace("false   # exit 1", "true   # exit 1"),
                       DOCUMENT.replace("$ hello", "$ hello; exit 4"),
                       "<!-- doc-test: expect-fail (x) -->\n```sh\ntrue\n```\n",
                       "<!-- doc-test: timeout 1 -->\n```sh\nsleep 30\n```\n"):
            check(not run_document(broken, source, build)[0], "fails:\n" + broken)
    finally:
        shutil.rmtree(top)


def run_self_test():
    check_parser()
    check_output_rule()
    check_verdicts()
    for failure in FAILURES:
        print("self-test FAILED:", failure)
    print(f"doc_test self-test: {len(FAILURES)} failures")
    return not FAILURES
