"""The HTML report of a growthuq run (tools/report, `growthuq report`): the run's CSV tables,
its provenance.json and the figures of tools/plotting gathered into one file that needs nothing
else to be read (figures embedded as PNG, no scripts, no fetched resources)."""
