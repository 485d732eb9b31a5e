"""Strings as h5py returns them: variable-length strings come back as str in attributes but as
bytes in compound fields and some arrays; these helpers turn either into str."""


def as_text(value):
    if isinstance(value, bytes):
        return value.decode("utf-8")
    return str(value)


def text_list(values):
    return [as_text(value) for value in values]


def text_attribute(node, name, default=None):
    if name not in node.attrs:
        return default
    return as_text(node.attrs[name])
