"""The package's exceptions: one hierarchy under GrowthuqError, so `except growthuq.GrowthuqError`
catches every failure the package reports. A failing CLI command raises the CliError subclass its
exit status names (src/cli/main.cpp: 2 bad input, 3 an internal error or memory exhausted,
128 + N stopped by signal N); each also derives from the built-in exception a caller would expect
(FileNotFoundError, ValueError, MemoryError, ...)."""


class GrowthuqError(Exception):
    """Every error the growthuq package raises."""


class CliNotFoundError(GrowthuqError, FileNotFoundError):
    """No growthuq CLI where the package looked (cli=, GROWTHUQ_CLI, PATH)."""


class ArgumentError(GrowthuqError, ValueError):
    """An argument no command can take (a NUL character), refused before anything runs."""


class ResultsError(GrowthuqError, ValueError):
    """A results directory or file that is missing or not growthuq's layout; the message names
    the file and what was expected."""


class CliError(GrowthuqError, RuntimeError):
    """growthuq exited with an error. str(error) is its message (its stderr); `returncode` and
    `command` (the argument list) tell what ran."""

    def __init__(self, message, returncode, command):
        super().__init__(message)
        self.returncode = returncode
        self.command = command


class InputError(CliError, ValueError):
    """Exit status 2: the CLI refused its input (a file, line, key or option), naming it, the value
    and what it expected; nothing was written."""


class InternalError(CliError):
    """Exit status 3: the CLI failed for a reason that is not its input (an internal error)."""


class OutOfMemoryError(InternalError, MemoryError):
    """Exit status 3 with "out of memory": the machine could not provide the memory the command
    needed (fewer samples need less)."""


class Interrupted(CliError):
    """The CLI was stopped by a signal (exit status 128 + N, or killed): SIGINT, SIGTERM, ...;
    a run removes its partial files and keeps its checkpoint."""


def cli_error(message, returncode, command):
    """The CliError subclass the exit status `returncode` names (subprocess gives -N for a
    process killed by signal N, the CLI 128 + N when it ends itself on one)."""
    if returncode == 2:
        return InputError(message, returncode, command)
    if returncode == 3:
        kind = OutOfMemoryError if "out of memory" in message else InternalError
        return kind(message, returncode, command)
    if returncode < 0 or returncode > 128:
        return Interrupted(message, returncode, command)
    return CliError(message, returncode, command)
