"""Reading a report back as a browser's DOM would: its tables (by id) as rows of cell text, its
images' sources, its sections' text. Shared by test_report.py and test_report_browser.py."""
from html.parser import HTMLParser


class ReportParser(HTMLParser):
    def __init__(self):
        super().__init__()
        self.tables = {}       # id: [[cell text]] (header row first)
        self.images = []       # src of every <img>
        self.sections = {}     # id: text
        self._table = None
        self._row = None
        self._cell = None
        self._section = None

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "table":
            self._table = attrs.get("id", "")
            self.tables[self._table] = []
        elif tag == "tr" and self._table is not None:
            self._row = []
        elif tag in ("td", "th") and self._row is not None:
            self._cell = ""
        elif tag == "img":
            self.images.append(attrs.get("src", ""))
        elif tag == "section":
            self._section = attrs.get("id", "")
            self.sections[self._section] = ""

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._cell is not None:
            self._row.append(self._cell.strip())
            self._cell = None
        elif tag == "tr" and self._row is not None:
            self.tables[self._table].append(self._row)
            self._row = None
        elif tag == "table":
            self._table = None
        elif tag == "section":
            self._section = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell += data
        if self._section is not None:
            self.sections[self._section] += data


def parse_report(text):
    parser = ReportParser()
    parser.feed(text)
    parser.close()
    return parser
