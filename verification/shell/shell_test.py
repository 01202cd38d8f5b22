#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The dabs shell as a person uses it, and dabs reading commands from a pipe.

Usage: shell_test.py path/to/dabs

Interactive: dabs runs in a pseudo-terminal (Python's pty module), so tclreadline loads its
library through Tcl's `load` (which the nodal `load` command must hand on) and gives the
`dabs> ` prompt. The test types commands with an error among them, recalls an earlier command
with the up-arrow key, and quits; the shell must survive the error and exit with status 0.
Piped: a failed command makes the exit status 1, a last command without its newline runs, and an
unclosed brace at the end of input is an error rather than silently dropped.
"""
import os
import pty
import select
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from check import check, finish  # noqa: E402

DABS = os.path.abspath(sys.argv[1])


class Terminal:
    """dabs on the slave side of a pseudo-terminal; reads everything it writes."""

    def __init__(self, home):
        env = dict(os.environ, HOME=home, TERM="xterm")
        self.pid, self.fd = pty.fork()
        if self.pid == 0:
            os.execve(DABS, [DABS], env)
        self.out = b""

    def read_until(self, text, timeout=20.0):
        end = time.time() + timeout
        while text.encode() not in self.out and time.time() < end:
            ready, _, _ = select.select([self.fd], [], [], 0.1)
            if ready:
                try:
                    chunk = os.read(self.fd, 4096)
                except OSError:
                    break
                if not chunk:
                    break
                self.out += chunk
        return text.encode() in self.out

    def type(self, keys):
        for ch in keys.encode():
            os.write(self.fd, bytes([ch]))
            time.sleep(0.005)

    def wait(self, timeout=20.0):
        end = time.time() + timeout
        while time.time() < end:
            pid, status = os.waitpid(self.pid, os.WNOHANG)
            if pid:
                return os.waitstatus_to_exitcode(status)
            self.read_until("\0", 0.1)
        os.kill(self.pid, 9)
        return None


def interactive():
    with tempfile.TemporaryDirectory() as home:
        t = Terminal(home)
        check(t.read_until("dabs> "), "the shell starts in a terminal with the dabs> prompt (tclreadline loaded)")
        t.type("model basic -ndm 1 -ndf 1\r")
        t.type("node 1 0.0; node 2 1.0\r")
        t.type("expr {6*7}\r")
        check(t.read_until("42"), "a command's result is shown")
        t.type("node x 0.0\r")
        check(t.read_until("expected an integer"), "an error is reported and names the argument")
        t.type("expr {100+23}\r")
        check(t.read_until("123"), "the shell goes on after the error")
        mark = len(t.out)
        # Up arrow three times: expr {100+23}, node x 0.0, expr {6*7}.
        t.type("\x1b[A\x1b[A\x1b[A\r")
        t.read_until("dabs> ", 5)
        time.sleep(0.5)
        t.read_until("\0", 0.5)
        check(b"42" in t.out[mark:], "the up-arrow key recalls an earlier command from the history")
        t.type("exit\r")
        code = t.wait()
        check(code == 0, f"exit quits with status 0 (got {code})")
        os.close(t.fd)


def piped(text):
    p = subprocess.run([DABS], input=text.encode(), capture_output=True, timeout=60)
    return p.returncode, p.stdout.decode(), p.stderr.decode()


def pipes():
    code, out, err = piped("puts first\nnosuchcommand\nputs last\n")
    check(code == 1 and "first" in out and "last" in out and "nosuchcommand" in err,
          f"a failed command in a pipe gives exit status 1, later commands still run (status {code})")
    code, out, _ = piped("puts one\nputs two")
    check(code == 0 and out.split() == ["one", "two"], "a last command without its newline runs")
    code, out, err = piped("puts one\nputs {two\n")
    check(code == 1 and "incomplete command" in err, f"an unclosed brace at end of input is an error (status {code})")
    code, out, _ = piped("model basic -ndm 1 -ndf 1\nnode 1 0.0\nputs [nodeCoord 1]\n")
    check(code == 0 and out.strip() == "0.0", f"a correct pipe exits with status 0 (status {code})")
    code, out, err = piped("load /no/such/library.so\n")
    check(code == 1 and "couldn't load file" in err, "load with a file name is Tcl's load")
    code, out, err = piped("model basic -ndm 1 -ndf 1\nnode 1 0.0\ntimeSeries Linear 1\n"
                           "pattern Plain 1 1 {load 1 5.0}\nputs ok\n")
    check(code == 0 and "ok" in out, "load with a node tag is the nodal load")


interactive()
pipes()
finish()
