"""What the report's reference runs share: reading a run's file kept in the repository, and the
files changed in the checkout since that run's commit.

A reference run is an analysis too long for the main job (the whole mutation analysis, every
module's perturbations), run once on a named commit and kept in the repository: it is true of
its commit, and the report says what has changed since (mutation_reference.py,
module_reach_reference.py).
"""
from __future__ import annotations

import json
import os
import subprocess


def read(source, relpath, fields, warnings):
    """The run's document, or None when the checkout keeps none, or (with a warning) when it
    cannot be read or lacks one of fields."""
    path = os.path.join(source, relpath)
    if not os.path.exists(path):
        return None
    try:
        with open(path, encoding="utf-8") as fh:
            doc = json.load(fh)
        missing = [f for f in fields if not isinstance(doc.get(f), list)]
        if missing:
            raise ValueError(f"no list {', '.join(missing)}")
    except (OSError, ValueError, AttributeError) as e:
        warnings.append(f"{relpath}: unreadable ({e}); the reference is left out")
        return None
    return doc


def changed_since(source, commit, paths):
    """The files under paths that differ between commit and the checkout's working tree; None
    when git cannot tell (no repository, the commit unknown here)."""
    try:
        out = subprocess.run(["git", "-C", source, "diff", "--name-only", commit, "--", *paths],
                             capture_output=True, text=True, timeout=60)
    except (OSError, subprocess.SubprocessError):
        return None
    if out.returncode != 0:
        return None
    return sorted(x for x in out.stdout.splitlines() if x.strip())


def since_text(changed, what):
    """What changed since the run's commit, in words: what names the files ("the mutated
    files")."""
    if changed is None:
        return "git cannot compare it with the checkout"
    if not changed:
        return f"{what} are unchanged in the checkout"
    names = ", ".join(os.path.basename(c) for c in changed[:6]) + (" ..." if len(changed) > 6 else "")
    return f"{len(changed)} of {what} changed in the checkout since ({names})"
