#!/usr/bin/env python3
"""Writes fsicontact(1), the man page, from the program's own help text (issue 31):
`fsicontact --help`, each subcommand's --help and --version, so that the page and the
program cannot disagree. Run by the build (app/CMakeLists.txt) after the program:
    scripts/manpage.py PROGRAM OUT.1
"""
import datetime
import re
import subprocess
import sys

EXIT_STATUS = [
    ("0", "solved (converged)."),
    ("1", "a failure after validation: a solver (the message names the phase and the solver's status) "
          "or a write (the file and the system's reason); summary.json says \"status\": \"failed\"."),
    ("2", "invalid input: the message names the file, the key and the allowed range; nothing is written."),
    ("3", "the coupling reached its iteration limit (outputs written, converged: false)."),
    ("128 + signal", "stopped by Ctrl-C (130), SIGTERM (143) or SIGHUP after the current iteration; "
                     "outputs written, \"status\": \"interrupted\"."),
]


def roff(text):
    """Text as roff sees it: backslashes and hyphens escaped, no line starting with a dot."""
    text = text.replace("\\", "\\e").replace("-", "\\-")
    return re.sub(r"^([.'])", r"\\&\1", text, flags=re.M)


def help_text(program, *args):
    done = subprocess.run([program, *args], capture_output=True, text=True, check=True)
    return done.stdout


def sections(text):
    """{heading: [(term, description)]} of CLI11's "Heading:" blocks of "  term   description" lines."""
    out, current = {}, None
    for line in text.splitlines():
        if re.match(r"^\S.*:$", line):
            current = out.setdefault(line[:-1], [])
        elif current is not None and line.startswith("  ") and line.strip():
            parts = re.split(r"\s{2,}", line.strip(), maxsplit=1)
            current.append((parts[0], parts[1] if len(parts) > 1 else ""))
    return out


def usage(program, command):
    """What follows the command on its help's "Usage:" line: "[OPTIONS] [case]"."""
    line = next(l for l in help_text(program, command, "--help").splitlines() if l.startswith("Usage:"))
    return line.split(" " + command + " ", 1)[1]


def items(pairs):
    return "".join(f".TP\n.B {roff(term)}\n{roff(desc)}\n" for term, desc in pairs)


def main():
    program, out = sys.argv[1], sys.argv[2]
    top = help_text(program, "--help")
    version = help_text(program, "--version").strip()
    summary = top.splitlines()[0].split(":", 1)[1].strip()
    commands = sections(top).get("Subcommands", [])
    date = datetime.date.today().isoformat()
    page = [f'.TH FSICONTACT 1 "{date}" "{roff(version.splitlines()[0])}" "User Commands"\n',
            f".SH NAME\nfsicontact \\- {roff(summary)}\n",
            ".SH SYNOPSIS\n" + "".join(f".B fsicontact {c}\n{roff(usage(program, c))}\n.br\n" for c, _ in commands) +
            ".B fsicontact\n\\-\\-version\n",
            ".SH DESCRIPTION\n" + roff(summary) + ". A case is a TOML file (its keys in docs/cases.md; examples in "
            "share/fsicontact/cases of the install); results go to an output directory with summary.json.\n",
            ".SH OPTIONS\n" + items(sections(top).get("Options", []))]
    for command, description in commands:
        text = help_text(program, command, "--help")
        page.append(f".SH COMMAND: {command.upper()}\n{roff(description)}.\n")
        parts = sections(text)
        page.append(items(parts.get("Positionals", []) + parts.get("Options", [])))
    page.append(".SH EXIT STATUS\n" + items(EXIT_STATUS))
    page.append(".SH VERSION\n.nf\n" + roff(version) + "\n.fi\n")
    page.append(".SH SEE ALSO\nThe README and docs/ (installed under share/doc/fsicontact): cases.md, theory.md, "
                "validation.md, performance.md, reliability.md.\n")
    with open(out, "w") as f:
        f.write("".join(page))


if __name__ == "__main__":
    main()
