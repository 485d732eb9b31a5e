"""Text as results.h5 holds it: h5py gives str for attributes but bytes inside compound tables
and string datasets."""


def text(value):
    return value.decode("utf-8") if isinstance(value, bytes) else str(value)


def texts(values):
    return [text(value) for value in values]
