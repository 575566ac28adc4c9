#!/usr/bin/env python3
"""Checks that every call of the core library that can throw has an error-returning twin.

    check_error_returning.py ROOT
    check_error_returning.py --self-test ROOT

A call "can throw" when the library defines it (declared, not defined, in a public header:
its body is compiled with the library's exceptions) and it is not marked noexcept: a member
function of a class marked TAMIAS2D_EXPORT, or a free function marked TAMIAS2D_EXPORT, in
include/tamias2d/*.hpp (the core target; io/ is the scene-file library). Destructors, deleted
and defaulted functions and the exception types themselves (a class deriving from a standard
exception or from another such class) are no calls.

For each such call `name(params) [const]` the same scope must declare
`Result<...> try_name(params) [const] noexcept` with the same parameter types (a constructor's
twin is `static Result<Class> try_create(params) noexcept`). The throwing form must be declared
inside `#if TAMIAS2D_EXCEPTIONS` (so that a game built without exceptions cannot call it by
mistake) and its twin outside it.

--self-test removes one twin at a time from a copy of the headers (and one guard) and fails
unless each removal is reported.
Exit status: 0 when every check passes, 1 when one fails, 2 for a bad command line.
"""
from __future__ import annotations

import functools
import re
import sys
from pathlib import Path

# Calls whose try_ forms are not declared yet: the user guide's "Without exceptions" section
# names them as the gap they are. An entry that is no longer needed is reported.
NOT_YET: set[str] = set()

CLASS_HEAD = re.compile(r"\b(class|struct)\s+(?:\[\[[^\]]*\]\]\s*)?(TAMIAS2D_EXPORT\s+)?(\w+)"
                        r"\s*(?::\s*(.*))?$", re.S)


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", lambda m: re.sub(r"[^\n]", " ", m.group(0)), text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def guarded_spans(text):
    """The preprocessor lines blanked out, and a per-character flag: inside a
    `#if TAMIAS2D_EXCEPTIONS` region."""
    out, flags, stack = [], [], []
    for line in text.splitlines(keepends=True):
        s = line.strip()
        if s.startswith("#"):
            directive = s[1:].strip()
            if directive.startswith(("if", "ifdef", "ifndef")):
                stack.append(bool(re.match(r"if\s+TAMIAS2D_EXCEPTIONS\s*$", directive)))
            elif directive.startswith("endif") and stack:
                stack.pop()
            elif directive.startswith("else") and stack and stack[-1]:
                stack[-1] = False  # the #else of the guard is the no-exceptions part
            out.append(re.sub(r"[^\n]", " ", line))
            flags.extend([any(stack)] * len(line))
            continue
        out.append(line)
        flags.extend([any(stack)] * len(line))
    return "".join(out), flags


def statements(text):
    """(scope, statement, has_body, guarded) for each statement directly in a namespace or a
    class. scope: None for a namespace, else (class name, exported, bases)."""
    text, flags = guarded_spans(strip_comments(text))
    out, stack, cur, start, paren, i = [], [], "", 0, 0, 0

    def scope():
        for s in reversed(stack):
            if s[0] == "class":
                return s[1:]
        return None

    def skip_braces(j):
        depth = 0
        while j < len(text):
            if text[j] == "{":
                depth += 1
            elif text[j] == "}":
                depth -= 1
                if depth == 0:
                    return j
            j += 1
        return j

    while i < len(text):
        c = text[i]
        if c in "([":
            paren += 1
        elif c in ")]":
            paren -= 1
        if c == "{" and paren == 0:
            head = " ".join(cur.split())
            head = re.sub(r"^(public|private|protected)\s*:(?!:)\s*", "", head)
            if re.search(r"\benum\b", head):
                i = skip_braces(i)
                cur += "{}"
            elif re.match(r"^namespace\b", head) or head.startswith("extern"):
                stack.append(("namespace",))
                cur = ""
            elif (m := CLASS_HEAD.search(head)) and "(" not in head.split(m.group(3))[0]:
                stack.append(("class", m.group(3), bool(m.group(2)), (m.group(4) or "").strip()))
                cur = ""
            elif "(" in head and not head.rstrip().endswith("="):
                out.append((scope(), head, True, flags[start] if start < len(flags) else False))
                i = skip_braces(i)
                cur = ""
            else:
                i = skip_braces(i)
                cur += "{}"
        elif c == "}" and paren == 0:
            if stack:
                stack.pop()
            cur = ""
        elif c == ";" and paren == 0:
            s = " ".join(cur.split())
            s = re.sub(r"^(public|private|protected)\s*:(?!:)\s*", "", s)
            if s:
                out.append((scope(), s, False, flags[start] if start < len(flags) else False))
            cur = ""
        else:
            if not cur.strip() and not c.isspace():
                start = i
            cur += c
        i += 1
    return out


def split_params(params):
    depth, cur, out = 0, "", []
    for c in params:
        if c in "<({[":
            depth += 1
        elif c in ">)}]":
            depth -= 1
        if c == "," and depth == 0:
            out.append(cur)
            cur = ""
        else:
            cur += c
    out.append(cur)
    return [p.strip() for p in out if p.strip()]


def param_type(p):
    p = re.split(r"\s=\s|=", p)[0].strip()
    m = re.match(r"^(.*?[\w>&*\]])\s+(\w+)$", p)
    t = m.group(1) if m and m.group(1) not in ("const", "unsigned") else p
    return re.sub(r"\s*([&*<>,])\s*", r"\1", t)


FUNC = re.compile(r"^(?P<pre>.*?)\b(?P<name>~?\w+|operator\s*\S+)\s*\((?P<params>.*)\)\s*"
                  r"(?P<const>const)?\s*(?P<noexcept>noexcept)?\s*(?P<eq>=\s*\w+)?\s*$", re.S)


@functools.lru_cache(maxsize=None)
def functions(text):
    """The functions the header declares or defines: dicts with scope, name, result, params
    (types), const, noexcept, static, has_body, deleted, guarded, exported."""
    out = []
    for scope, s, has_body, guarded in statements(text):
        if s.startswith(("friend", "using", "typedef", "static_assert", "template")):
            s = re.sub(r"^template\s*<[^>]*>\s*", "", s)
            if s.startswith(("friend", "using", "typedef", "static_assert")):
                continue
        if has_body:
            s = s.split(") :")[0] + ")" if ") :" in s else s
        m = FUNC.match(s)
        if not m or "(" not in s:
            continue
        pre, name = m.group("pre"), m.group("name")
        if pre.rstrip().endswith("~"):
            pre, name = pre.rstrip()[:-1], "~" + name
        words = pre.replace("[[nodiscard]]", "").split()
        exported = "TAMIAS2D_EXPORT" in words
        static = "static" in words
        result = " ".join(w for w in words if w not in ("TAMIAS2D_EXPORT", "static", "explicit",
                                                         "inline", "constexpr", "virtual"))
        out.append(dict(scope=scope, name=name, result=result,
                        params=tuple(param_type(p) for p in split_params(m.group("params"))),
                        const=bool(m.group("const")), noexcept=bool(m.group("noexcept")),
                        static=static, has_body=has_body,
                        deleted=bool(m.group("eq")), guarded=guarded, exported=exported))
    return out


def is_call(f, exception_types):
    """Whether f is a call of the library that needs a try_ twin."""
    scope = f["scope"]
    if scope is None:
        library = f["exported"]
    else:
        name, exported, bases = scope
        library = exported and name not in exception_types
    if not library or f["has_body"] or f["deleted"] or f["noexcept"]:
        return False
    return not (f["name"].startswith(("~", "try_", "operator")))


def exception_types(headers):
    """Classes deriving from a standard exception, or from such a class."""
    found, changed = set(), True
    heads = []
    for text in headers.values():
        for m in re.finditer(r"\b(?:class|struct)\s+(?:TAMIAS2D_EXPORT\s+)?(\w+)\s*:\s*([^{;]*)\{",
                             strip_comments(text)):
            heads.append((m.group(1), m.group(2)))
    while changed:
        changed = False
        for name, bases in heads:
            if name not in found and (re.search(r"std::(\w+_error|invalid_argument|exception|"
                                                r"logic_error|bad_\w+)\b", bases)
                                      or any(re.search(rf"\b{b}\b", bases) for b in found)):
                found.add(name)
                changed = True
    return found


def check(headers):
    problems, calls = [], 0
    exc = exception_types(headers)
    for path, text in sorted(headers.items()):
        fs = functions(text)
        for f in fs:
            if not is_call(f, exc) or f["name"] in NOT_YET:
                continue
            calls += 1
            cls = f["scope"][0] if f["scope"] else None
            ctor = cls is not None and f["name"] == cls
            twin = "try_create" if ctor else "try_" + f["name"]
            where = f"{cls}::" if cls else ""
            label = f"{path}: {where}{f['name']}({', '.join(f['params'])})"
            matches = [g for g in fs if g["scope"] == f["scope"] and g["name"] == twin and
                       g["params"] == f["params"] and (ctor or g["const"] == f["const"])]
            if not matches:
                problems.append(f"{label} can throw and has no {twin} with the same parameters")
                continue
            g = matches[0]
            if not g["noexcept"]:
                problems.append(f"{label}: its {twin} is not noexcept")
            if not g["result"].startswith("Result<"):
                problems.append(f"{label}: its {twin} returns {g['result']}, not a Result")
            if ctor and not g["static"]:
                problems.append(f"{label}: its {twin} is not static")
            if not f["guarded"]:
                problems.append(f"{label} is declared outside #if TAMIAS2D_EXCEPTIONS")
            if g["guarded"]:
                problems.append(f"{label}: its {twin} is declared inside #if TAMIAS2D_EXCEPTIONS")
    for name in sorted(NOT_YET):
        if not any(f["name"] == name for t in headers.values() for f in functions(t)):
            problems.append(f"NOT_YET names {name}, which no public header declares")
        elif any(f["name"] == "try_" + name for t in headers.values() for f in functions(t)):
            problems.append(f"NOT_YET names {name}, which has its try_ form now")
    return problems, calls


def self_test(headers):
    """Each damage must be reported; the undamaged headers must pass."""
    problems, _ = check(headers)
    if problems:
        return ["the headers fail before any damage"] + problems
    failures, tried = [], 0
    for path, text in sorted(headers.items()):
        for m in re.finditer(r"^\s*[^/\n]*\btry_\w+\s*\([^;]*;", text, re.M):
            tried += 1
            damaged = dict(headers)
            damaged[path] = text[:m.start()] + text[m.end():]
            if not check(damaged)[0]:
                failures.append(f"removing {m.group(0).strip()[:60]!r} from {path} is not reported")
            if tried % 7 == 0:
                # the same removal with noexcept dropped instead
                damaged[path] = text[:m.start()] + m.group(0).replace(" noexcept", "") + \
                    text[m.end():]
                if " noexcept" in m.group(0) and not check(damaged)[0]:
                    failures.append(f"dropping noexcept from {m.group(0).strip()[:60]!r} "
                                    "is not reported")
        first_if = text.find("#if TAMIAS2D_EXCEPTIONS\n")
        if first_if >= 0:
            damaged = dict(headers)
            damaged[path] = text.replace("#if TAMIAS2D_EXCEPTIONS\n", "#if 1\n", 1)
            if not check(damaged)[0]:
                failures.append(f"unguarding the first throwing block of {path} is not reported")
    if tried < 100:
        failures.append(f"only {tried} try_ declarations found to remove")
    print(f"check_error_returning: self-test: {tried} removals, {len(failures)} not reported")
    return failures


def main(argv):
    test = "--self-test" in argv
    args = [a for a in argv if a != "--self-test"]
    if len(args) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    root = Path(args[0])
    headers = {str(p.relative_to(root)): p.read_text(encoding="utf-8")
               for p in sorted((root / "include/tamias2d").glob("*.hpp"))}
    if not headers:  # a wrong root would otherwise check nothing and pass
        print(f"check_error_returning: no public headers under {root / 'include/tamias2d'}")
        return 1
    problems = self_test(headers) if test else check(headers)[0]
    for p in problems:
        print(f"check_error_returning: {p}")
    if not test:
        print(f"check_error_returning: {check(headers)[1]} calls that can throw, "
              f"{'OK' if not problems else f'{len(problems)} problems'}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
