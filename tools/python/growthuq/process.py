"""One CLI command as a child process: stdout collected, stderr collected and, when asked, shown
live on sys.stderr as the CLI writes it (its progress: a line per plant line, the curve fits, the
bootstrap's replicates), so a long `growthuq.run(..., quiet=False)` is not silent. A failure
raises the CliError of its exit status with the CLI's message."""
import codecs
import re
import signal
import subprocess
import sys
import threading

from .errors import cli_error


def _pump(pipe, kept, show):
    """Reads `pipe` chunk by chunk (as the CLI flushes it) into `kept`, echoing to sys.stderr."""
    decoder = codecs.getincrementaldecoder("utf-8")(errors="replace")
    for chunk in iter(lambda: pipe.read1(65536), b""):
        text = decoder.decode(chunk)
        kept.append(text)
        if show and text:
            sys.stderr.write(text)
            sys.stderr.flush()
    kept.append(decoder.decode(b"", final=True))


# The CLI's error line (src/cli/main.cpp): "growthuq run: error: ..." or "... internal error: ...".
_ERROR_LINE = re.compile(r"^growthuq[^:\n]*: (?:internal )?error: ", re.MULTILINE)


def _message(stderr, stdout, returncode):
    """The CLI's message: its error line and what follows, without the progress before it."""
    found = _ERROR_LINE.search(stderr)
    text = stderr[found.start():] if found else stderr
    return text.strip() or stdout.strip() or f"exited with {returncode}"


def call(command, cwd, show_progress):
    """Runs `command` (the argument list) in `cwd`; returns (stdout, stderr) as text. Ctrl-C
    (KeyboardInterrupt) is passed on to the CLI as SIGINT, so a run removes its partial files as
    on the command line, and is raised again once it has ended."""
    process = subprocess.Popen(command, cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE)
    errors = []
    reader = threading.Thread(target=_pump, args=(process.stderr, errors, show_progress), daemon=True)
    reader.start()
    try:
        stdout = process.stdout.read()
        process.wait()
    except KeyboardInterrupt:
        process.send_signal(signal.SIGINT)
        process.wait()
        raise
    finally:
        reader.join()
        process.stdout.close()
        process.stderr.close()
    stdout, stderr = stdout.decode("utf-8", errors="replace"), "".join(errors)
    if process.returncode != 0:
        raise cli_error(_message(stderr, stdout, process.returncode), process.returncode, command)
    return stdout, stderr
