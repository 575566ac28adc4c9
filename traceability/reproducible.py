"""The same results give the same report, byte for byte, wherever the checkout lies.

The report's one time of its own is `generated` (--date, SOURCE_DATE_EPOCH or now). Everything
else is a function of the inputs: this module removes what would otherwise vary between two
regenerations from the same results:

* absolute paths: every string of the report that names a path under the source root names it
  relative to the root (the root itself is "."), so a checkout or scratch copy in another
  directory gives the same bytes;
* the order of unordered collections: a set that reaches the JSON is written sorted (Python
  randomises the order of sets of strings per process).

Times that are data of the evidence (a verification program's run time, the test run's start
and finish, measured durations) come from the results files and are the same at every
regeneration from them.
"""
from __future__ import annotations

import datetime as _dt
import json
import os
import re
import subprocess

EPOCH = "1970-01-01T00:00:00Z"


def portable(obj, root):
    """obj with every path under root written relative to it (in place for dicts and lists;
    returns the new value)."""
    root = os.path.abspath(root).rstrip(os.sep)
    if not root:
        return obj  # the filesystem root: every path is under it, none is made shorter
    prefix = root + os.sep

    # The root as a whole path ("the build in /x/repo is stale"), not a longer name.
    bare = re.compile(re.escape(root) + r"(?![\w.-])")

    def fix(s):
        if root not in s:
            return s
        return bare.sub(".", s.replace(prefix, ""))

    def walk(x):
        if isinstance(x, str):
            return fix(x)
        if isinstance(x, dict):
            for k in list(x):
                x[k] = walk(x[k])
            return x
        if isinstance(x, list):
            for i, v in enumerate(x):
                x[i] = walk(v)
            return x
        if isinstance(x, (set, frozenset)):
            return sorted(walk(v) for v in x)
        if isinstance(x, tuple):
            return [walk(v) for v in x]
        return x

    return walk(obj)


def _default(o):
    if isinstance(o, (set, frozenset)):
        return sorted(o, key=str)
    return str(o)


def dumps(obj):
    """The report's JSON text: fixed indentation, key order as built, sets sorted."""
    return json.dumps(obj, indent=1, sort_keys=False, default=_default, ensure_ascii=False) + "\n"


def commit_date(root):
    """The committer date of the checkout's HEAD as an xsd:dateTime in UTC, or None."""
    try:
        proc = subprocess.run(["git", "-C", root, "show", "-s", "--format=%cI", "HEAD"],
                              capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.TimeoutExpired):
        return None
    return iso_utc(proc.stdout.strip()) if proc.returncode == 0 else None


def iso_utc(text):
    """An ISO 8601 or report timestamp ("2026-11-29 10:00 UTC") as YYYY-MM-DDTHH:MM:SSZ, or
    None when it is neither."""
    if not text:
        return None
    t = str(text).strip()
    for fmt in ("%Y-%m-%d %H:%M UTC", "%Y-%m-%d %H:%M:%S UTC", "%Y-%m-%d"):
        try:
            d = _dt.datetime.strptime(t, fmt).replace(tzinfo=_dt.timezone.utc)
            return d.strftime("%Y-%m-%dT%H:%M:%SZ")
        except ValueError:
            pass
    try:
        d = _dt.datetime.fromisoformat(t.replace("Z", "+00:00"))
    except ValueError:
        return None
    if d.tzinfo is None:
        d = d.replace(tzinfo=_dt.timezone.utc)
    return d.astimezone(_dt.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
