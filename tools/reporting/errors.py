"""Bad input stops the report with one line naming the file (and column or key), the value found
and what was expected, exit status 2, as growthuq's own errors do."""


class ReportInputError(Exception):
    pass
