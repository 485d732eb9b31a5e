"""The two ways a figure does not get made: bad input (the command stops with one line and exit
status 2, as growthuq's own errors) and a figure whose data the campaign does not have (it is
skipped with a one-line note; the other figures are still made)."""


class PlotInputError(Exception):
    """Bad input: the message names the file (and dataset, column or key), the value found and
    what was expected."""


class FigureSkipped(Exception):
    """The campaign lacks what this figure needs; the message says what and how to get it."""
