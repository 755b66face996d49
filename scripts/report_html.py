#!/usr/bin/python3
"""The HTML pieces of report.html (scripts/report.py): escaping, paragraphs,
the line of a missing file, numbers as the tables print them (4 significant
digits, the CSV text kept in a cell's data-value), tables, embedded PNG
images, and the readers of the folder's JSON and CSV files. Standard library
only."""
import base64
import csv
import html
import json
import math
import os


def esc(text):
    return html.escape(str(text), quote=True)


def missing(text):
    return '<p class="missing">%s</p>\n' % esc(text)


def para(text, cls=None):
    return "<p%s>%s</p>\n" % (' class="%s"' % cls if cls else "", esc(text))


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def is_number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def fmt(x):
    """x with 4 significant digits (text left as it is)."""
    if isinstance(x, bool):
        return "yes" if x else "no"
    if is_number(x):
        return "%.4g" % x
    value = number(x)
    if isinstance(x, str) and x.strip() and not math.isnan(value):
        return "%.4g" % value
    return "" if x is None else str(x)


def cell(x, value=None):
    """A <td>: numbers right-aligned with 4 digits, @value (the exact text)
    in its data-value attribute when given."""
    numeric = is_number(x) or (isinstance(x, str) and not math.isnan(number(x)))
    attributes = ' class="num"' if numeric else ""
    if value is not None:
        attributes += ' data-value="%s"' % esc(value)
    return "<td%s>%s</td>" % (attributes, esc(fmt(x)))


def text_cell(x):
    """A <td> of @x as it is (a parameter's value: never rounded)."""
    return "<td>%s</td>" % esc("" if x is None else x)


def table(header, rows, cls=None):
    """An HTML table; each row a list of cell() texts or plain values."""
    out = ['<table%s>' % (' class="%s"' % cls if cls else ""), "<tr>"]
    out += ["<th>%s</th>" % esc(h) for h in header]
    out.append("</tr>\n")
    for r in rows:
        out.append("<tr>" + "".join(c if isinstance(c, str) and c.startswith("<td")
                                    else cell(c) for c in r) + "</tr>\n")
    out.append("</table>\n")
    return "".join(out)


def image_tag(data, alt):
    return '<img alt="%s" src="data:image/png;base64,%s">\n' % (
        esc(alt), base64.b64encode(data).decode("ascii"))


def read_json(path):
    """(the parsed JSON or None, a line saying why not)."""
    if not os.path.isfile(path):
        return None, "no %s" % os.path.basename(path)
    try:
        with open(path) as f:
            return json.load(f), ""
    except (OSError, ValueError) as e:
        return None, "%s cannot be read (%s)" % (os.path.basename(path), e)


def read_table(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))
