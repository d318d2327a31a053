#!/usr/bin/python3
"""End-to-end tests of the certimesh CLI's options (issue 12, item 14).

usage:
  cli_options_test.py help <certimesh>        every subcommand's --help: exit 0, each option
                                              named with its default, each one parsed
  cli_options_test.py extensions <certimesh>  an unsupported output extension is refused
                                              before any work, and nothing is written
  cli_options_test.py missing_ele <certimesh> check X.node without X.ele names X.ele, exit 2

The option lists below are the specification, written independently of the tool's help text.
"""
import os
import subprocess
import sys
import tempfile

# command -> [(option, value or None for a flag, has a default)]
OPTIONS = {
    "mesh": [("-o", "out.vtu", False), ("--output", "out.vtu", False), ("--size", "0.5", True),
             ("--gamma", "1.5", True), ("--grading", "0.3", True), ("--algorithm", "front", True),
             ("--certificate", "c.json", True), ("--svg", "p.svg", True),
             ("--save-domain", "d.poly", True), ("--no-improve", None, True),
             ("--quiet", None, True)],
    "check": [("--domain", "d.poly", True), ("--certificate", "c.json", True)],
    "predicates": [("--mode", "exact", True), ("--line-buffered", None, True)],
    "convert": [],
    "domain": [("-o", "out.poly", False)],
    "check-surface": [],
    "demo": [],
    "fuzz": [("--seconds", "5", True), ("--cases", "10", True), ("--seed", "1", True),
             ("--jobs", "1", True), ("--keep-going", None, True), ("--report", "r.json", True),
             ("--out", ".", True), ("--list", None, False), ("--replay", "x.repro", False)],
}
MESH_OUTPUTS = [".mesh", ".msh", ".vtu", ".node", ".ele"]
CONVERT_OUTPUTS = [".node", ".ele", ".face", ".poly", ".mesh", ".msh", ".vtu"]

failures = []


def check(cond, message):
    if not cond:
        failures.append(message)
        print("FAIL:", message)


def run(certimesh, args, cwd, timeout=60):
    """Exit status, stdout, stderr; a run past `timeout` is killed and reads as exit None."""
    try:
        p = subprocess.run([certimesh] + args, cwd=cwd, stdin=subprocess.DEVNULL,
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=timeout,
                           check=False)
    except subprocess.TimeoutExpired:
        return None, "", "timed out after %d s" % timeout
    return p.returncode, p.stdout.decode(), p.stderr.decode()


def option_entry(lines, option):
    """The help lines describing `option`: its line and its continuation lines."""
    for i, line in enumerate(lines):
        words = line.strip().replace(",", " ").split()
        if words and words[0].startswith("-") and option in words[:3]:
            entry = [line]
            for more in lines[i + 1:]:
                if not more.strip() or more.strip().startswith("-"):
                    break
                entry.append(more)
            return " ".join(entry)
    return None


def test_help(certimesh):
    with tempfile.TemporaryDirectory() as tmp:
        for command, options in OPTIONS.items():
            for flag in ("--help", "-h"):
                rc, out, err = run(certimesh, [command, flag], tmp)
                check(rc == 0, "%s %s: exit %d, stderr %r" % (command, flag, rc, err))
                check(out.startswith("usage: certimesh " + command),
                      "%s %s: no usage line: %r" % (command, flag, out[:80]))
            lines = out.splitlines()
            for option, _, has_default in options:
                entry = option_entry(lines, option)
                check(entry is not None, "%s --help does not name %s" % (command, option))
                if entry is not None and has_default:
                    check("default" in entry, "%s --help: %s without its default: %r" %
                          (command, option, entry))
            # --help wins over other arguments, wherever it stands.
            rc, out2, _ = run(certimesh, [command, "some-input", "--help"], tmp)
            check(rc == 0 and out2 == out, "%s X --help: exit %d or other text" % (command, rc))
        check_options_parsed(certimesh, tmp)
        check(os.listdir(tmp) == [], "help runs wrote files: %r" % os.listdir(tmp))


def check_options_parsed(certimesh, tmp):
    """Every option the help names is one the parser knows (help and parser cannot drift)."""
    for command, options in OPTIONS.items():
        for option, value, _ in options:
            args = [command, option] + ([value] if value is not None else [])
            if command == "predicates" or (command, option) == ("fuzz", "--list"):
                rc, out, err = run(certimesh, args, tmp)
                check(rc == 0, "%s %s: exit %d, %r" % (command, option, rc, err))
                continue
            # The required positional argument is missing, so nothing runs; the complaint
            # must be about that, not about the option.
            rc, out, err = run(certimesh, args, tmp)
            check(rc == 2 and "unexpected argument" not in err and "unknown option" not in err,
                  "%s: %s not accepted: exit %d, %r" % (command, option, rc, err))


def test_extensions(certimesh):
    with tempfile.TemporaryDirectory() as tmp:
        # A size that would take hours: only a refusal before any work returns at once.
        for out in ["out.xyz", "out", "out.poly", "out.vtu.bak"]:
            rc, stdout, err = run(certimesh, ["mesh", "builtin:plate", "-o", out, "--size", "1e-6"],
                                  tmp, timeout=20)
            ext = os.path.splitext(out)[1]
            check(rc == 2, "mesh -o %s: exit %d" % (out, rc))
            check(err.startswith("error: ") and ("'%s'" % ext) in err and
                  all(e in err for e in MESH_OUTPUTS),
                  "mesh -o %s: message does not name the extension and the supported ones: %r" %
                  (out, err))
            check(stdout == "", "mesh -o %s: work was done: %r" % (out, stdout[:200]))
            check(os.listdir(tmp) == [], "mesh -o %s wrote %r" % (out, os.listdir(tmp)))
        # Supported extensions are still written (the refusal is not a blanket one).
        rc, _, err = run(certimesh, ["mesh", "builtin:square", "-o", "sq.node", "--quiet"], tmp)
        check(rc == 0 and os.path.exists(os.path.join(tmp, "sq.ele")), "mesh -o sq.node: %d %r" % (rc, err))
        before = sorted(os.listdir(tmp))
        rc, stdout, err = run(certimesh, ["convert", "sq.node", "sq.xyz"], tmp)
        check(rc == 2 and "'.xyz'" in err and all(e in err for e in CONVERT_OUTPUTS),
              "convert to .xyz: exit %d, %r" % (rc, err))
        check(sorted(os.listdir(tmp)) == before, "convert to .xyz wrote %r" % os.listdir(tmp))
        rc, _, err = run(certimesh, ["convert", "sq.node", "sq.msh"], tmp)
        check(rc == 0 and os.path.exists(os.path.join(tmp, "sq.msh")), "convert to .msh: %d %r" % (rc, err))


def test_missing_ele(certimesh):
    with tempfile.TemporaryDirectory() as tmp:
        node = os.path.join(tmp, "X.node")
        with open(node, "w") as f:
            f.write("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n")
        rc, out, err = run(certimesh, ["check", node], tmp)
        ele = os.path.join(tmp, "X.ele")
        check(rc == 2, "check X.node without X.ele: exit %d" % rc)
        check(err.startswith("error: %s: " % ele), "check X.node: stderr does not name %s: %r" % (ele, err))
        # With its .ele the same command certifies (the refusal is about the missing file).
        rc, _, err = run(certimesh, ["mesh", "builtin:square", "-o", "X.node", "--quiet"], tmp)
        check(rc == 0, "mesh -o X.node: %d %r" % (rc, err))
        rc, out, err = run(certimesh, ["check", node], tmp)
        check(rc == 0 and "valid" in out, "check X.node with X.ele: exit %d, %r %r" % (rc, out, err))


def main():
    what, certimesh = sys.argv[1], os.path.abspath(sys.argv[2])
    {"help": test_help, "extensions": test_extensions, "missing_ele": test_missing_ele}[what](certimesh)
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
