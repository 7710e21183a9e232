#!/usr/bin/env python3
"""Documentation that runs: every command block of a Markdown file, executed against the build.

    doc_test.py --source DIR --build DIR [--data DIR] FILE.md ...
    doc_test.py --self-test

Every fenced block whose language is sh, bash, shell or console is a command block. Each runs as
a bash script (`set -e -o pipefail`) in a fresh sandbox that looks like the repository root
(docs/ copied, so a command that writes under docs/ changes the copy; every other top-level entry
a symbolic link to the source tree; build/ the build directory; ../shared/data the test data),
with build/bin/ first on PATH, its output (stdout and stderr together) kept, and a time limit.
A block passes when it exits 0 and its quoted output matches; the file passes when every block
does. The markers, how output is compared and why blocks are skipped: docs/documentation.md.
"""

import argparse
import contextlib
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

COMMAND_LANGUAGES = {"sh", "bash", "shell", "console"}
DEFAULT_TIMEOUT_S = 60
# A block that names the shared test data is skipped where it is absent, as the C++ tests are.
TEST_DATA_PATH = "../shared/data"
MARKER = re.compile(r"^\s*<!--\s*doc-test:\s*(.*?)\s*-->\s*$")
FENCE = re.compile(r"^(\s*)(`{3,}|~{3,})\s*([\w+-]*)")
# `# exit N` closing a command's line: the exit code the doc says that command ends with.
EXPECTED_EXIT = re.compile(r"#\s*exit\s+(\d+)\b")
QUOTED = r'"((?:[^"\\]|\\.)*)"'
NUMBER = r"-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?"
ELISION = re.compile(r"^\s*\.{3,}\s*$")


class DocError(Exception):
    """A marker the test cannot read: the doc is wrong, not the command."""


class Block:
    """One fenced block: where it starts, its language and text, the markers above it."""

    def __init__(self, line, language, text, markers):
        self.line = line
        self.language = language
        self.text = text
        self.skip = None            # the reason it is not run
        self.expect_fail = None     # the reason it is expected to fail (temporary)
        self.replacements = []      # (old, new, reason): the reduced form that runs
        self.timeout = DEFAULT_TIMEOUT_S
        self.is_output = False      # compared with the output of the command block before it
        self.seconds = 0.0          # how long it ran
        self.compared = 0           # the quoted outputs compared (a console block's, an output block)
        for marker in markers:
            self.read_marker(marker)

    def read_marker(self, marker):
        word, _, rest = marker.partition(" ")
        if word in ("skip", "expect-fail"):
            reason = re.fullmatch(r"\((.+)\)", rest.strip())
            if not reason:
                raise DocError(f"line {self.line}: '{word}' needs its reason in parentheses")
            setattr(self, word.replace("-", "_"), reason.group(1))
        elif word == "replace":
            parts = re.fullmatch(QUOTED + r"\s+" + QUOTED + r"\s+\((.+)\)", rest.strip())
            if not parts:
                raise DocError(f"line {self.line}: replace \"OLD\" \"NEW\" (reason), not '{rest}'")
            old, new = (p.replace('\\"', '"') for p in parts.group(1, 2))
            self.replacements.append((old, new, parts.group(3)))
        elif word == "timeout" and rest.strip().isdigit():
            self.timeout = int(rest)
        elif word == "output" and not rest:
            self.is_output = True
        else:
            raise DocError(f"line {self.line}: unknown doc-test marker '{marker}'")

    def is_command(self):
        return self.language in COMMAND_LANGUAGES and not self.is_output

    def script_text(self):
        """The text that runs: the block with its replacements made, each one required to apply."""
        text = self.text
        for old, new, _ in self.replacements:
            if old not in text:
                raise DocError(f"line {self.line}: replace \"{old}\": not in the block")
            text = text.replace(old, new)
        return text


def parse_blocks(markdown):
    """The fenced blocks of a Markdown text, each with the doc-test markers just above it."""
    blocks, markers, lines = [], [], markdown.splitlines()
    i = 0
    while i < len(lines):
        fence = FENCE.match(lines[i])
        if not fence:
            marker = MARKER.match(lines[i])
            markers = markers + [marker.group(1)] if marker else []
            i += 1
            continue
        close = re.compile(r"^\s*" + re.escape(fence.group(2)[0]) + "{%d,}\\s*$" % len(fence.group(2)))
        end = i + 1
        while end < len(lines) and not close.match(lines[end]):
            end += 1
        indent = len(fence.group(1))
        body = [line[indent:] if line[:indent].isspace() else line for line in lines[i + 1:end]]
        if not fence.group(3):
            raise DocError(f"line {i + 1}: a fence without a language: sh or console runs, text "
                           "does not")
        blocks.append(Block(i + 1, fence.group(3).lower(), "\n".join(body) + "\n", markers))
        markers, i = [], end + 1
    return blocks


def console_commands(text):
    """A console block as (command, expected output lines): `$ ` starts a command, a trailing
    backslash continues it, every other line is that command's output."""
    commands, continued = [], False
    for line in text.splitlines():
        if continued:
            commands[-1][0].append(line)
        elif line.startswith("$ "):
            commands.append(([line[2:]], []))
        elif commands:
            commands[-1][1].append(line)
        else:
            raise DocError(f"output before the first '$ ' command: '{line}'")
        continued = line.endswith("\\") and not commands[-1][1]
    return [("\n".join(command), output) for command, output in commands]


def with_expected_exits(script):
    """The script with each command whose line ends in `# exit N` checked to end with N."""
    out, command = [], []
    for line in script.splitlines():
        command.append(line)
        if line.rstrip().endswith("\\"):
            continue
        expected = EXPECTED_EXIT.search(line)
        if expected:
            code = expected.group(1)
            out += ["set +e"] + command + [
                "doc_test_rc=$?", "set -e",
                f'[ "$doc_test_rc" = {code} ] || {{ echo "doc-test: exit $doc_test_rc where the '
                f'doc says {code}: {command[0].strip()}" >&2; exit 1; }}']
        else:
            out += command
        command = []
    return "\n".join(out + command) + "\n"


# -- comparing quoted output --------------------------------------------------------------------

def line_pattern(expected):
    """A quoted line as a regex: `..` (or more dots) stands for anything (timings, elided
    fields), a run of spaces for any run, a number for a number that rounds to it."""
    parts = []
    for token in re.finditer(r"(\.{2,})|(\s+)|(" + NUMBER + r")|(.)", expected.strip()):
        dots, space, number, char = token.groups()
        parts.append(".*?" if dots else r"\s+" if space else
                     f"({NUMBER})" if number else re.escape(char))
    return re.compile(r"\s*" + "".join(parts) + r"\s*")


def rounds_to(actual, quoted):
    """Whether a printed number agrees with the doc's to the digits the doc quotes."""
    mantissa, _, exponent = quoted.lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    tolerance = 0.5 * 10.0 ** (int(exponent or 0) - decimals)
    return abs(float(actual) - float(quoted)) <= tolerance * (1 + 1e-9)


def line_matches(expected, actual):
    match = line_pattern(expected).fullmatch(actual)
    if not match:
        return False
    quoted = re.findall(NUMBER, re.sub(r"\.{2,}", " ", expected))
    return all(rounds_to(a, q) for a, q in zip(match.groups(), quoted))


def output_matches(expected, actual):
    """Line by line; a line of `...` alone stands for any number of lines."""
    expected = [line for line in expected if line.strip()]
    actual = [line for line in actual if line.strip()]
    memo = {}

    def match_from(e, a):
        if (e, a) not in memo:
            if e == len(expected):
                memo[(e, a)] = a == len(actual)
            elif ELISION.match(expected[e]):
                memo[(e, a)] = any(match_from(e + 1, k) for k in range(a, len(actual) + 1))
            else:
                memo[(e, a)] = (a < len(actual) and line_matches(expected[e], actual[a])
                                and match_from(e + 1, a + 1))
        return memo[(e, a)]
    return match_from(0, 0)


# -- running ------------------------------------------------------------------------------------

# The build's directories a block reads (the executables, the Python module, the messages' jar), each given as a directory of links to its files: a block
# that builds (a launch script without --no-build) then configures a build of its own in the
# sandbox, which fails or times out, instead of reconfiguring the one under test for the
# sandbox's paths; the build tree itself is $DOC_TEST_BUILD (for cmake --install).
BUILD_OUTPUTS = ("bin", "python", "lcmtypes")


def make_sandbox(source, build, data, python):
    """A temporary directory standing for the repository root, beside ../shared/data; HOME."""
    top = tempfile.mkdtemp(prefix="doc_test_")
    root = os.path.join(top, "repo")
    os.mkdir(root)
    for entry in os.listdir(source):
        if entry not in (".git", "build", "docs"):
            os.symlink(os.path.join(source, entry), os.path.join(root, entry))
    shutil.copytree(os.path.join(source, "docs"), os.path.join(root, "docs"))
    for output in BUILD_OUTPUTS:
        os.makedirs(os.path.join(root, "build", output))
        built = os.path.join(build, output)
        for name in os.listdir(built) if os.path.isdir(built) else []:
            os.symlink(os.path.join(built, name), os.path.join(root, "build", output, name))
    if python:  # python3: the interpreter the build's module was built for
        os.makedirs(os.path.join(root, "build", "interpreter"))
        os.symlink(python, os.path.join(root, "build", "interpreter", "python3"))
    if data and os.path.isdir(data):
        os.mkdir(os.path.join(top, "shared"))
        os.symlink(os.path.abspath(data), os.path.join(top, "shared", "data"))
    return top, root


class Stopped(Exception):
    """ctest's timeout (SIGTERM): the block's processes are ended before the test is."""


def stop_on_sigterm():
    def handler(signum, frame):
        raise Stopped()
    signal.signal(signal.SIGTERM, handler)


def run_script(script, root, build, timeout):
    """(exit code or None on timeout, output): the script in its own process group, every
    process it left behind (a node sent to the background) ended with it."""
    path = [os.path.join(root, "build", "bin"), os.path.join(root, "build", "interpreter")]
    env = dict(os.environ, DOC_TEST_BUILD=build, HOME=os.path.dirname(root),
               PATH=os.pathsep.join(path + [os.environ["PATH"]]))
    with open(os.path.join(root, ".doc_test_output"), "w+b") as log:
        process = subprocess.Popen(["bash", "-c", "set -e -o pipefail\n" + script], cwd=root,
                                   env=env, stdin=subprocess.DEVNULL, stdout=log,
                                   stderr=subprocess.STDOUT, start_new_session=True)
        try:
            code = process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            code = None
        finally:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(process.pid, signal.SIGKILL)
            process.wait()
        log.seek(0)
        return code, log.read().decode("utf-8", "replace")


SEPARATOR = "@@doc-test: next command@@"


def block_script(block):
    """The bash text of a command block; for a console block, its commands between separators."""
    text = block.script_text()
    if block.language != "console":
        return with_expected_exits(text), None
    commands = console_commands(text)
    script = "".join(with_expected_exits(command) + f"printf '\\n%s\\n' '{SEPARATOR}'\n"
                     for command, _ in commands)
    return script, [output for _, output in commands]


def check_block(block, root, build, previous_output):
    """A failure message, or None when the block passes; and the output it printed."""
    if block.is_output:
        if previous_output is None:
            return "an output block with no command block run before it", None
        block.compared = 1
        return (None if output_matches(block.text.splitlines(), previous_output.splitlines())
                else "the output differs from the doc's:\n" + previous_output), None
    script, quoted = block_script(block)
    start = time.monotonic()
    code, output = run_script(script, root, build, block.timeout)
    block.seconds = time.monotonic() - start
    if code is None:
        return f"still running after {block.timeout} s (a doc-test: timeout N marker?)", output
    if code != 0:
        return f"exit {code}:\n{output}", output
    printed = output.split(SEPARATOR)
    for number, (expected, actual) in enumerate(zip(quoted or [], printed), 1):
        if expected:
            block.compared += 1
            if not output_matches(expected, actual.splitlines()):
                return f"command {number}'s output differs from the doc's:\n{actual}", output
    return None, output


def run_file(path, source, build, data, python=None):
    """Runs every command block of one Markdown file; prints each and the counts; True if all
    passed."""
    name = os.path.relpath(path, source)
    with open(path, encoding="utf-8") as f:
        try:
            blocks = parse_blocks(f.read())
        except DocError as error:
            raise DocError(f"{name}: {error}")
    have_data = bool(data) and os.path.isdir(data)
    counts = {"run": 0, "compared": 0, "skipped": 0, "expected to fail": 0, "failed": 0}
    top, root = make_sandbox(source, build, data, python)
    previous_output, ok = None, True
    try:
        for block in blocks:
            if not block.is_command() and not block.is_output:
                continue
            skip = block.skip or (None if have_data or TEST_DATA_PATH not in block.text
                                  else f"the test data {data} is absent")
            if skip:
                counts["skipped"] += 1
                print(f"{name}:{block.line}: skipped ({skip})")
                previous_output = None
                continue
            failure, output = check_block(block, root, build, previous_output)
            if block.is_command():
                previous_output = output
                counts["run"] += 1
            counts["compared"] += block.compared
            ok &= report(name, block, failure, counts)
    finally:
        shutil.rmtree(top, ignore_errors=True)
    print(f"{name}: " + ", ".join(f"{n} {what}" for what, n in counts.items()))
    return ok


def report(name, block, failure, counts):
    """Prints one block's result; False if it fails the file."""
    where = f"{name}:{block.line}"
    reduced = "".join(f" [reduced: {reason}]" for _, _, reason in block.replacements)
    if block.expect_fail:
        counts["expected to fail"] += 1
        if failure is None:
            counts["failed"] += 1
            print(f"{where}: FAILED: passes, but is marked expect-fail ({block.expect_fail}): "
                  "remove the marker")
            return False
        print(f"{where}: failed as expected ({block.expect_fail}): {failure.splitlines()[0]}")
        return True
    if failure is not None:
        counts["failed"] += 1
        print(f"{where}: FAILED: {failure}")
        return False
    print(f"{where}: ok ({block.seconds:.1f} s){reduced}")
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", help="the repository root")
    parser.add_argument("--build", help="the build directory (its bin/ first on PATH)")
    parser.add_argument("--data", help="the test data (default SOURCE/../shared/data)")
    parser.add_argument("--python", help="python3 in a block: the interpreter of the build's "
                        "Python module (CMake's Python3_EXECUTABLE)")
    parser.add_argument("--self-test", action="store_true", help="check the parser and matcher")
    parser.add_argument("files", nargs="*")
    args = parser.parse_args()
    if args.self_test:
        from doc_test_selftest import run_self_test
        return 0 if run_self_test() else 1
    if not (args.source and args.build and args.files):
        parser.error("--source, --build and at least one FILE are required")
    source, build = os.path.abspath(args.source), os.path.abspath(args.build)
    data = args.data or os.environ.get("BILLIARD_TEST_DATA") or os.path.join(source, "..", "shared", "data")
    stop_on_sigterm()
    try:
        results = [run_file(os.path.abspath(f), source, build, os.path.abspath(data), args.python)
                   for f in args.files]
    except DocError as error:
        print(f"doc_test: {error}", file=sys.stderr)
        return 2
    except Stopped:
        print("doc_test: stopped (SIGTERM)", file=sys.stderr)
        return 1
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
