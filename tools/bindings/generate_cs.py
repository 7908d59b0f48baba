#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Write the C# interop of the Unity package from frusta.h: the enums and constants, the
id handles, the struct mirrors and the P/Invoke declarations, so that a header change
costs one run of this script. The hand-written, idiomatic layer (World, Hand, Device,
the partial structs in Structs.cs) sits on top.

    python3 tools/bindings/generate_cs.py            rewrite unity-package/Runtime/Binding/Generated/
    python3 tools/bindings/generate_cs.py --check    exit 1 (with a diff) if those files are stale

It reads the header with a small parser of its own, not a C compiler's: comments and
macro names are what the binding is made of (docs, fixed-buffer sizes), and a
preprocessor drops both. The header is ours and regular, so the parser knows exactly the
forms it uses and stops, naming the line, at anything else rather than guess:

- `#ifndef FRUSTA_BASE_X` / `#define FRUSTA_BASE_X` / ... / `#endif`: a block the engine's
  base header copies (generate_base.py); read as if the guard were not there.
- `#define FRUSTA_X <number or arithmetic on earlier constants>`  -> FrustaConstants.X;
  function-like macros are C conveniences and are skipped; inside #if blocks only the
  export macros may be defined.
- `typedef enum e { E_A = 1, ... } e;`  -> enum, members without their common prefix.
  An enum whose doc says its values are "bits" is [Flags].
- `typedef struct s { ... } s;`  -> [StructLayout(Sequential)] partial struct, member for
  member. A struct named *_id (index1, world0, generation) -> an id handle with value
  equality. Field types: fixed-width integers, float, double, earlier structs, and arrays
  of them; no pointers (the ABI has none).
- `FRUSTA_API ret name(params);`  -> Native.name, Cdecl, exact spelling; pointers stay
  pointers (const char* is byte*), ids and structs go by value.

Names: types and public fields are PascalCase (frusta_world_def.max_objects ->
FrustaWorldDef.MaxObjects), constants lose FRUSTA_, parameters are camelCase. Each
field is either public under its PascalCase name, or internal under its C name where
the idiomatic layer wraps it or the binding manages it:
- struct_size, internal_value, reserved*: the binding fills them;
- 0/1 flags (an int32_t whose comment starts "1:" or "1 if"): a bool property wraps them;
- arrays other than vectors: C# reaches fixed buffers only in unsafe code, so accessors
  wrap them. A double[3] is a Vector3d and a double[4] a Quaterniond (x, y, z, w).
An int32_t whose comment starts with the name of one of the header's enums has that
enum's type. Comments become the docs: a /** */ before a declaration, and a field's or
member's own comment (after it, or on the lines just above it).
"""
import argparse
import difflib
import os
import re
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
HEADER = os.path.join(ROOT, "native", "include", "frusta", "frusta.h")
OUTPUT = os.path.join(ROOT, "unity-package", "Runtime", "Binding", "Generated")
SELF = "tools/bindings/generate_cs.py"

PRIMITIVES = {"int8_t": "sbyte", "uint8_t": "byte", "int16_t": "short", "uint16_t": "ushort",
              "int32_t": "int", "uint32_t": "uint", "int64_t": "long", "uint64_t": "ulong",
              "float": "float", "double": "double"}
# one-dimensional double arrays the binding reads as its vector types
VIEWS = {("double", 3): "Vector3d", ("double", 4): "Quaterniond"}
# what the export block at the top of the header may define, in its #if branches
LINKAGE_MACROS = {"FRUSTA_EXPORT", "FRUSTA_API"}
# error codes lose ERROR_ as well as the common FRUSTA_: FrustaResult.StaleId
MEMBER_PREFIXES = {"frusta_result": "FRUSTA_ERROR_"}
ID_FIELDS = [("int32_t", "index1"), ("uint16_t", "world0"), ("uint16_t", "generation")]
CS_KEYWORDS = set("""abstract as base bool break byte case catch char checked class const continue
decimal default delegate do double else enum event explicit extern false finally fixed float for
foreach goto if implicit in int interface internal is lock long namespace new null object operator
out override params private protected public readonly ref return sbyte sealed short sizeof
stackalloc static string struct switch this throw true try typeof uint ulong unchecked unsafe
ushort using virtual void volatile while""".split())


class HeaderError(Exception):
    pass


# ---------------------------------------------------------------- lexing

class Token:
    def __init__(self, kind, text, line):
        self.kind, self.text, self.line = kind, text, line

    def __repr__(self):
        return f"{self.text!r} (line {self.line})"


class Comment:
    """A comment and where it stands: before token number `at` of the token list."""

    def __init__(self, text, first, last, at):
        self.text, self.first, self.last, self.at = text, first, last, at
        self.is_doc = text.startswith("/**")


class Directive:
    def __init__(self, text, line, at):
        self.text, self.line, self.at = text, line, at


TOKEN = re.compile(r"\s+|/\*.*?\*/|//[^\n]*|[A-Za-z_]\w*|0[xX][0-9A-Fa-f]+|\d+(?:\.\d*)?(?:[eE][-+]?\d+)?"
                   r"|\S", re.S)


def lex(text):
    tokens, comments, directives = [], [], []
    pos, line = 0, 1
    at_line_start = True
    while pos < len(text):
        if at_line_start and re.match(r"[ \t]*#", text[pos:pos + 80]):
            # a directive runs to the end of the line, continued by backslashes
            end = pos
            while True:
                nl = text.find("\n", end)
                nl = len(text) if nl < 0 else nl
                if text[end:nl].rstrip().endswith("\\"):
                    end = nl + 1
                    continue
                break
            raw = text[pos:nl]
            body = re.sub(r"/\*.*?\*/", " ", raw.replace("\\\n", " "), flags=re.S)
            directives.append(Directive(" ".join(body.split()), line, len(tokens)))
            line += raw.count("\n")
            pos = nl
            continue
        m = TOKEN.match(text, pos)
        s = m.group(0)
        if s.startswith("/*") or s.startswith("//"):
            comments.append(Comment(s, line, line + s.count("\n"), len(tokens)))
        elif not s.isspace():
            kind = "id" if re.match(r"[A-Za-z_]", s) else "num" if s[0].isdigit() else "punct"
            tokens.append(Token(kind, s, line))
        if s.isspace():
            at_line_start = "\n" in s or at_line_start
        else:
            at_line_start = False
        line += s.count("\n")
        pos = m.end()
    return tokens, comments, directives


def comment_text(c):
    """The words of a comment, one string per line, without the comment's marks."""
    body = c.text[3:] if c.is_doc else c.text[2:]
    if c.text.startswith("/*"):
        body = body[:-2]
    lines = [re.sub(r"^\s*\*?", "", l).strip() for l in body.split("\n")]
    while lines and not lines[0]:
        lines.pop(0)
    while lines and not lines[-1]:
        lines.pop()
    return lines


# ---------------------------------------------------------------- the model

class Constant:
    def __init__(self, c_name, tokens, doc):
        self.c_name, self.tokens, self.doc = c_name, tokens, doc
        self.value = None


class Enum:
    def __init__(self, c_name, doc):
        self.c_name, self.doc, self.members, self.flags = c_name, doc, [], False


class Field:
    def __init__(self, c_type, c_name, dims, doc, remarks):
        self.c_type, self.c_name, self.dims, self.doc, self.remarks = c_type, c_name, dims, doc, remarks


class Struct:
    def __init__(self, c_name, doc):
        self.c_name, self.doc, self.fields = c_name, doc, []

    @property
    def is_id(self):
        return self.c_name.endswith("_id")


class Param:
    def __init__(self, c_type, pointers, c_name):
        self.c_type, self.pointers, self.c_name = c_type, pointers, c_name


class Function:
    def __init__(self, c_name, ret, params, doc):
        self.c_name, self.ret, self.params, self.doc = c_name, ret, params, doc


class Header:
    def __init__(self):
        self.constants, self.enums, self.structs, self.functions = [], [], [], []

    def enum(self, c_name):
        return next((e for e in self.enums if e.c_name == c_name), None)

    def struct(self, c_name):
        return next((s for s in self.structs if s.c_name == c_name), None)

    def constant(self, c_name):
        return next((c for c in self.constants if c.c_name == c_name), None)


# ---------------------------------------------------------------- parsing

class Parser:
    def __init__(self, text, path):
        self.path = path
        self.tokens, self.comments, self.directives = lex(text)
        self.i = 0
        self.header = Header()

    def fail(self, message, line=None):
        if line is None:
            line = self.tokens[min(self.i, len(self.tokens) - 1)].line if self.tokens else 1
        raise HeaderError(f"{self.path}:{line}: {message}")

    def peek(self, k=0):
        j = self.i + k
        if j < len(self.tokens):
            return self.tokens[j]
        return Token("end", "the header's end", self.tokens[-1].line if self.tokens else 1)

    def take(self, text=None, kind=None):
        t = self.peek()
        if (text is not None and t.text != text) or (kind is not None and t.kind != kind):
            self.fail(f"expected {text or kind}, found {t.text!r}", t.line)
        self.i += 1
        return t

    # comments --------------------------------------------------------

    def doc_before(self, at, line):
        """The /** */ comment that ends on the line above a declaration."""
        for c in self.comments:
            if c.at == at and c.is_doc and c.last == line - 1:
                return comment_text(c)
        return []

    def member_docs(self, first, end):
        """Own and group comments of the member spanning tokens [first, end): the comment
        after it on its last line, and the comments on the lines just above it."""
        last_line = self.tokens[end - 1].line
        after = [c for c in self.comments if c.at == end and c.first == last_line]
        prev_line = self.tokens[first - 1].line if first > 0 else 0
        above = [c for c in self.comments if c.at == first and c.first != prev_line]
        chain, next_line = [], self.tokens[first].line
        for c in reversed(above):
            if c.last < next_line - 1:
                break
            chain.insert(0, c)
            next_line = c.first
        own = [l for c in after for l in comment_text(c)]
        group = [l for c in chain for l in comment_text(c)]
        if not own:
            return group, []
        return own, group

    # directives ------------------------------------------------------

    def directives_(self):
        stack = []  # one entry per open #if: "guard" for the include guard
        pending_guard = None
        for n, d in enumerate(self.directives):
            words = d.text[1:].split(None, 1)
            name, rest = (words + [""])[0], (words + ["", ""])[1]
            inside = any(s != "guard" for s in stack)
            if name in ("if", "ifdef", "ifndef"):
                if name == "ifndef" and ((not stack and n == 0) or rest.strip().startswith("FRUSTA_BASE_")):
                    # the include guard, or a block core/base.h copies (generate_base.py)
                    pending_guard = rest.strip()
                    stack.append("guard")
                else:
                    stack.append("cond")
            elif name in ("elif", "else"):
                if not stack or stack[-1] == "guard":
                    self.fail(f"#{name} outside a conditional block", d.line)
            elif name == "endif":
                if not stack:
                    self.fail("#endif without #if", d.line)
                stack.pop()
            elif name == "include":
                if rest.strip() != "<stdint.h>":
                    self.fail(f"#include {rest}: the binding knows only <stdint.h>", d.line)
            elif name == "define":
                m = re.match(r"([A-Za-z_]\w*)(\()?\s*(.*)$", rest)
                if not m:
                    self.fail(f"#define {rest}: not understood", d.line)
                macro, function_like, body = m.group(1), m.group(2), m.group(3).strip()
                if inside:
                    if macro not in LINKAGE_MACROS:
                        self.fail(f"{macro} is defined inside #if: the binding cannot tell which branch holds", d.line)
                elif macro == pending_guard and not body:
                    pending_guard = None
                elif function_like:
                    continue  # a C convenience (FRUSTA_IS_NULL): nothing to bind
                elif macro in LINKAGE_MACROS:
                    self.fail(f"{macro} outside the export block", d.line)
                else:
                    self.constant(macro, body, d)
            else:
                self.fail(f"#{name}: not understood", d.line)
            # nothing but directives inside a conditional block
            if any(s != "guard" for s in stack) and n + 1 < len(self.directives):
                if self.directives[n + 1].at != d.at:
                    self.fail("declarations inside #if: the binding cannot tell which branch holds", d.line)
        if stack:
            self.fail("an #if block is not closed", self.directives[-1].line)

    def constant(self, macro, body, d):
        if not macro.startswith("FRUSTA_"):
            self.fail(f"{macro}: constants are named FRUSTA_*", d.line)
        if not body:
            self.fail(f"{macro} has no value", d.line)
        toks, _, _ = lex(body)
        for t in toks:
            if t.kind == "id" and not self.header.constant(t.text):
                self.fail(f"{macro}: {t.text} is not a constant defined above it", d.line)
            if t.kind == "punct" and t.text not in "()+-*/":
                self.fail(f"{macro}: {t.text!r} in a constant; only arithmetic on numbers and constants", d.line)
        c = Constant(macro, toks, self.doc_before(d.at, d.line))
        c.value = evaluate(toks, self.header, lambda m: self.fail(f"{macro}: {m}", d.line))
        self.header.constants.append(c)

    # declarations ----------------------------------------------------

    def parse(self):
        self.directives_()
        while self.peek().kind != "end":
            t = self.peek()
            if t.text == "typedef" and self.peek(1).text == "enum":
                self.enum_()
            elif t.text == "typedef" and self.peek(1).text == "struct":
                self.struct_()
            elif t.text == "FRUSTA_API":
                self.function()
            else:
                self.fail(f"{t.text!r}: the binding knows typedef enum, typedef struct and FRUSTA_API declarations")
        return self.header

    def known_type(self, name):
        return name in PRIMITIVES or self.header.struct(name) or self.header.enum(name)

    def enum_(self):
        start = self.i
        line = self.take("typedef").line
        self.take("enum")
        name = self.take(kind="id").text
        e = Enum(name, self.doc_before(start, line))
        self.take("{")
        while self.peek().text != "}":
            first = self.i
            member = self.take(kind="id")
            self.take("=")
            sign = -1 if self.peek().text == "-" and self.take("-") else 1
            value = self.take(kind="num")
            if not re.fullmatch(r"\d+|0[xX][0-9A-Fa-f]+", value.text):
                self.fail(f"{member.text}: enum values are integer literals", value.line)
            if self.peek().text == ",":
                self.take(",")
            elif self.peek().text != "}":
                self.fail(f"expected , or }} after {member.text}")
            doc, remarks = self.member_docs(first, self.i)
            e.members.append((member.text, sign * int(value.text, 0), doc, remarks, member.line))
        self.take("}")
        if self.take(kind="id").text != name:
            self.fail(f"typedef enum {name} must be named {name}")
        self.take(";")
        if not e.members:
            self.fail(f"{name} has no members", line)
        if re.search(r"\bbits\b", " ".join(e.doc)):
            e.flags = True
            for m in e.members:
                if m[1] <= 0 or m[1] & (m[1] - 1):
                    self.fail(f"{m[0]} = {m[1]}: {name} is documented as bits, so each value is a power of two", m[4])
        self.header.enums.append(e)

    def struct_(self):
        start = self.i
        line = self.take("typedef").line
        self.take("struct")
        name = self.take(kind="id").text
        s = Struct(name, self.doc_before(start, line))
        self.take("{")
        while self.peek().text != "}":
            first = self.i
            if self.peek().text == "const":
                self.fail(f"{name}: const fields are not part of the ABI")
            c_type = self.take(kind="id").text
            if c_type not in PRIMITIVES and not self.header.struct(c_type):
                if self.header.enum(c_type):
                    self.fail(f"{name}: store {c_type} as int32_t (enums have no fixed width in C)")
                self.fail(f"{name}: {c_type} is not a fixed-width type or a struct defined above")
            declarators = []
            while True:
                if self.peek().text == "*":
                    self.fail(f"{name}: pointers in structs are not part of the ABI")
                field = self.take(kind="id")
                dims = []
                while self.peek().text == "[":
                    self.take("[")
                    dims.append(self.dimension())
                    self.take("]")
                if dims and c_type not in PRIMITIVES:
                    self.fail(f"{name}.{field.text}: an array of {c_type}; C# fixed buffers hold primitives "
                              f"only: flatten it into numbers, or teach {SELF} a wrapper type", field.line)
                declarators.append((field, dims))
                if self.peek().text == ",":
                    self.take(",")
                    continue
                self.take(";")
                break
            doc, remarks = self.member_docs(first, self.i)
            for field, dims in declarators:
                s.fields.append(Field(c_type, field.text, dims, doc, remarks))
        self.take("}")
        if self.take(kind="id").text != name:
            self.fail(f"typedef struct {name} must be named {name}")
        self.take(";")
        if s.is_id and [(f.c_type, f.c_name, f.dims) for f in s.fields] != [(t, n, []) for t, n in ID_FIELDS]:
            self.fail(f"{name}: an id is {{int32_t index1; uint16_t world0; uint16_t generation;}}", line)
        self.header.structs.append(s)

    def dimension(self):
        t = self.take()
        if t.kind == "num" and re.fullmatch(r"\d+", t.text):
            return t.text
        c = self.header.constant(t.text) if t.kind == "id" else None
        if c is None or not isinstance(c.value, int):
            self.fail(f"array size {t.text}: an integer literal or an integer constant", t.line)
        return t.text

    def type_(self, what):
        """A return or parameter type; C# has no const, so it is read and dropped."""
        if self.peek().text == "const":
            self.take("const")
        name = self.take(kind="id").text
        if name not in ("char", "void") and not self.known_type(name):
            self.fail(f"{what}: {name} is not a fixed-width type or a type defined above")
        pointers = 0
        while self.peek().text == "*":
            self.take("*")
            pointers += 1
        if name == "char" and pointers != 1:
            self.fail(f"{what}: char only as a C string (const char*)")
        return name, pointers

    def function(self):
        start = self.i
        line = self.take("FRUSTA_API").line
        ret = self.type_("return type")
        name = self.take(kind="id").text
        if not name.startswith("frusta_"):
            self.fail(f"{name}: functions are named frusta_*")
        self.take("(")
        params = []
        if self.peek().text == "void" and self.peek(1).text == ")":
            self.take("void")
        while self.peek().text != ")":
            c_type, pointers = self.type_(f"{name}'s parameter")
            if c_type == "void" and pointers == 0:
                self.fail(f"{name}: a void parameter")
            pname = self.take(kind="id").text
            if self.peek().text == "[":  # an array parameter is a pointer
                self.take("[")
                self.dimension()
                self.take("]")
                pointers += 1
            params.append(Param(c_type, pointers, pname))
            if self.peek().text == ",":
                self.take(",")
        self.take(")")
        self.take(";")
        self.header.functions.append(Function(name, ret, params, self.doc_before(start, line)))


def evaluate(tokens, header, fail):
    """The value of a constant's arithmetic, as C computes it (int or double)."""
    pos = [0]

    def peek():
        return tokens[pos[0]].text if pos[0] < len(tokens) else None

    def atom():
        t = tokens[pos[0]] if pos[0] < len(tokens) else fail("the expression ends early")
        pos[0] += 1
        if t.text == "(":
            v = sum_()
            if peek() != ")":
                fail("unbalanced parentheses")
            pos[0] += 1
            return v
        if t.text == "-":
            return -atom()
        if t.kind == "num":
            return int(t.text, 0) if re.fullmatch(r"\d+|0[xX][0-9A-Fa-f]+", t.text) else float(t.text)
        if t.kind == "id":
            return header.constant(t.text).value
        fail(f"{t.text!r} in an expression")

    def product():
        v = atom()
        while peek() in ("*", "/"):
            op = tokens[pos[0]].text
            pos[0] += 1
            w = atom()
            if op == "*":
                v = v * w
            elif isinstance(v, int) and isinstance(w, int):
                v = int(v / w) if abs(v) < 2**52 else fail("integer division out of range")
            else:
                v = v / w
        return v

    def sum_():
        v = product()
        while peek() in ("+", "-"):
            op = tokens[pos[0]].text
            pos[0] += 1
            v = v + product() if op == "+" else v - product()
        return v

    v = sum_()
    if pos[0] != len(tokens):
        fail(f"{tokens[pos[0]].text!r} after the expression")
    if isinstance(v, int) and not -2**31 <= v < 2**31:
        fail(f"{v} does not fit an int")
    return v


# ---------------------------------------------------------------- names and types

def pascal(snake):
    return "".join(w[:1].upper() + w[1:].lower() for w in snake.split("_") if w)


def camel(snake):
    p = pascal(snake)
    name = p[:1].lower() + p[1:]
    return "@" + name if name in CS_KEYWORDS else name


def constant_name(c_name):
    return pascal(c_name[len("FRUSTA_"):])


def common_prefix(names):
    words = [n.split("_") for n in names]
    k = 0
    while all(len(w) > k + 1 for w in words) and len({tuple(w[:k + 1]) for w in words}) == 1:
        k += 1
    return "_".join(words[0][:k]) + "_" if k else ""


def member_names(e):
    names = [m[0] for m in e.members]
    prefixes = [p for p in (common_prefix(names), MEMBER_PREFIXES.get(e.c_name)) if p]
    out = []
    for n in names:
        strip = max((p for p in prefixes if n.startswith(p) and len(n) > len(p)), key=len, default="")
        cs = pascal(n[len(strip):])
        if not cs or cs[0].isdigit():
            raise HeaderError(f"{e.c_name}: {n} leaves no C# name once {strip} is taken off")
        out.append(cs)
    return out


def is_managed(field):
    """Fields the binding fills itself."""
    return field.c_name in ("struct_size", "internal_value") or re.fullmatch(r"reserved\d*", field.c_name)


def is_flag(field):
    return field.c_type == "int32_t" and not field.dims and bool(field.doc) and \
        re.match(r"1(:| if\b)", field.doc[0]) is not None


def enum_of(field, header):
    if field.c_type != "int32_t" or field.dims or not field.doc:
        return None
    word = re.match(r"[A-Za-z_]\w*", field.doc[0])
    return header.enum(word.group(0)) if word else None


def type_name(c_name, header):
    if c_name in PRIMITIVES:
        return PRIMITIVES[c_name]
    if header.enum(c_name) or header.struct(c_name):
        return pascal(c_name)
    return {"void": "void", "char": "byte"}[c_name]


class Layout:
    """How one C field is mirrored: its C# type, name, visibility and fixed-buffer size."""

    def __init__(self, field, header):
        f = field
        length = int(f.dims[0]) if len(f.dims) == 1 and f.dims[0].isdigit() else None
        self.view = VIEWS.get((f.c_type, length))
        self.fixed = bool(f.dims) and not self.view
        enum = enum_of(f, header)
        self.type = self.view or (pascal(enum.c_name) if enum else type_name(f.c_type, header))
        self.raw = bool(is_managed(f)) or is_flag(f) or self.fixed
        self.name = f.c_name if self.raw else pascal(f.c_name)
        self.size = " * ".join(constant_ref(d, header) for d in f.dims) if self.fixed else None


def constant_ref(token, header):
    c = header.constant(token)
    return f"FrustaConstants.{constant_name(c.c_name)}" if c else token


# ---------------------------------------------------------------- writing

BANNER = ("// SPDX-License-Identifier: MIT\n"
          f"// Generated by {SELF} from native/include/frusta/frusta.h: do not edit.\n"
          f"// Change the header, then run python3 {SELF}.\n")


def xml(s):
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def doc_lines(indent, lines, fallback, remarks=()):
    """/// <summary> of a comment's lines (or of the fallback, XML already), its paragraphs
    (separated by blank lines) as <para>, and a group comment as <remarks>."""
    pad = " " * indent
    paragraphs, current = [], []
    for l in [xml(l) for l in lines] or [fallback]:
        if l:
            current.append(l)
        elif current:
            paragraphs.append(current)
            current = []
    if current:
        paragraphs.append(current)
    if len(paragraphs) == 1 and len(paragraphs[0]) == 1 and not remarks:
        return [f"{pad}/// <summary>{paragraphs[0][0]}</summary>"]
    out = [f"{pad}/// <summary>"]
    for n, p in enumerate(paragraphs):
        if n == 0:
            out += [f"{pad}/// {l}" for l in p]
        else:
            out += [f"{pad}/// <para>"] + [f"{pad}/// {l}" for l in p] + [f"{pad}/// </para>"]
    out.append(f"{pad}/// </summary>")
    if remarks:
        out += [f"{pad}/// <remarks>"] + [f"{pad}/// {xml(l)}" for l in remarks if l] + [f"{pad}/// </remarks>"]
    return out


def file_text(usings, body):
    head = BANNER + "".join(f"using {u};\n" for u in usings)
    return head + "\nnamespace Frusta.Binding\n{\n" + "\n\n".join(body) + "\n}\n"


def expression(tokens):
    parts = [constant_name(t.text) if t.kind == "id" else t.text for t in tokens]
    text = ""
    for p in parts:
        if p in ("*", "/", "+", "-") and text and not text.endswith("("):
            text += f" {p} "
        else:
            text += p
    # one pair of parentheses around the whole body is C's macro hygiene, not meaning
    if text.startswith("(") and text.endswith(")"):
        depth = 0
        for n, ch in enumerate(text):
            depth += ch == "("
            depth -= ch == ")"
            if depth == 0 and n < len(text) - 1:
                break
        else:
            text = text[1:-1]
    return text


def write_enums(h):
    body = []
    for e in h.enums:
        lines = doc_lines(4, e.doc, f"<c>{e.c_name}</c>")
        if e.flags:
            lines.append("    [Flags]")
        lines += [f"    public enum {pascal(e.c_name)}", "    {"]
        for (c_name, value, doc, remarks, _), cs in zip(e.members, member_names(e)):
            lines += doc_lines(8, doc, f"<c>{c_name}</c>", remarks)
            lines.append(f"        {cs} = {value},")
        lines.append("    }")
        body.append("\n".join(lines))
    lines = ["    /// <summary>The header's constants (<c>FRUSTA_*</c>).</summary>",
             "    public static partial class FrustaConstants", "    {"]
    for c in h.constants:
        cs_type = "int" if isinstance(c.value, int) else "double"
        lines += doc_lines(8, c.doc, f"<c>{c.c_name}</c>")
        lines.append(f"        public const {cs_type} {constant_name(c.c_name)} = {expression(c.tokens)};")
    lines.append("    }")
    body.append("\n".join(lines))
    return file_text(["System"], body)


ID_MEMBERS = """\
        /// <summary>The null handle (all zero).</summary>
        public static {T} Null => default;

        /// <summary>true for the null handle (<see cref="Index1"/> is 0).</summary>
        public readonly bool IsNull => Index1 == 0;

        /// <summary>Field-wise equality.</summary>
        /// <param name="other">The handle to compare with.</param>
        /// <returns>true when both name the same slot, world and generation.</returns>
        public readonly bool Equals({T} other) =>
            Index1 == other.Index1 && World0 == other.World0 && Generation == other.Generation;

        /// <summary>Field-wise equality with a boxed handle.</summary>
        /// <param name="obj">The object to compare with.</param>
        /// <returns>true when obj is an equal handle.</returns>
        public override readonly bool Equals(object obj) => obj is {T} o && Equals(o);

        /// <summary>A hash of the three fields.</summary>
        /// <returns>The hash code.</returns>
        public override readonly int GetHashCode() => Index1 * 31 + (World0 << 16 | Generation);

        /// <summary>Field-wise equality.</summary>
        /// <param name="a">The first handle.</param>
        /// <param name="b">The second handle.</param>
        /// <returns>true when equal.</returns>
        public static bool operator ==({T} a, {T} b) => a.Equals(b);

        /// <summary>Field-wise inequality.</summary>
        /// <param name="a">The first handle.</param>
        /// <param name="b">The second handle.</param>
        /// <returns>true when different.</returns>
        public static bool operator !=({T} a, {T} b) => !a.Equals(b);

        /// <summary>"{{index1, world0, generation}}".</summary>
        /// <returns>The text.</returns>
        public override readonly string ToString() => $"{{{{{{Index1}}, {{World0}}, {{Generation}}}}}}";"""


def struct_lines(s, h, extra_doc=()):
    layouts = [Layout(f, h) for f in s.fields]
    unsafe = "unsafe " if any(l.fixed for l in layouts) else ""
    cs = pascal(s.c_name)
    lines = doc_lines(4, s.doc + list(extra_doc), f"<c>{s.c_name}</c>")
    lines.append("    [StructLayout(LayoutKind.Sequential)]")
    lines.append(f"    public {unsafe}partial struct {cs}" + (f" : IEquatable<{cs}>" if s.is_id else ""))
    lines.append("    {")
    for f, l in zip(s.fields, layouts):
        lines += doc_lines(8, f.doc, f"<c>{s.c_name}.{f.c_name}</c>", f.remarks)
        access = "internal" if l.raw else "public"
        if l.fixed:
            lines.append(f"        {access} fixed {l.type} {l.name}[{l.size}];")
        else:
            lines.append(f"        {access} {l.type} {l.name};")
    return lines


def write_ids(h):
    body = []
    for s in h.structs:
        if s.is_id:
            lines = struct_lines(s, h)
            lines.append("")
            lines += ID_MEMBERS.format(T=pascal(s.c_name)).split("\n")
            lines.append("    }")
            body.append("\n".join(lines))
    return file_text(["System", "System.Runtime.InteropServices"], body)


def write_structs(h):
    body = []
    for s in h.structs:
        if not s.is_id:
            body.append("\n".join(struct_lines(s, h) + ["    }"]))
    # the load-time check compares every mirror with the library's frusta_struct_size
    lines = ["    public static unsafe partial class FrustaLibrary", "    {",
             "        /// <summary>Every struct of frusta.h this binding mirrors.</summary>",
             "        internal static readonly Mirror[] Mirrors =", "        {"]
    for s in h.structs:
        cs = pascal(s.c_name)
        lines.append(f'            new Mirror("{s.c_name}", typeof({cs}), sizeof({cs})),')
    lines += ["        };", "    }"]
    body.append("\n".join(lines))
    return file_text(["System.Runtime.InteropServices"], body)


def parameter_type(c_type, pointers, h):
    return type_name(c_type, h) + "*" * pointers


def write_native(h):
    lines = ["    /// <summary>Every FRUSTA_API function of frusta.h, by its C name.</summary>",
             "    internal static unsafe partial class Native", "    {"]
    for n, f in enumerate(h.functions):
        if n:
            lines.append("")
        lines += doc_lines(8, f.doc, f"<c>{f.c_name}</c>")
        params = ", ".join(f"{parameter_type(p.c_type, p.pointers, h)} {camel(p.c_name)}" for p in f.params)
        lines.append("        [DllImport(Lib.Name, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]")
        lines.append(f"        internal static extern {parameter_type(f.ret[0], f.ret[1], h)} {f.c_name}({params});")
    lines.append("    }")
    return file_text(["System.Runtime.InteropServices"], ["\n".join(lines)])


def generate(header_path):
    with open(header_path, encoding="utf-8") as f:
        h = Parser(f.read(), os.path.relpath(header_path, ROOT)).parse()
    return {"Enums.g.cs": write_enums(h), "Ids.g.cs": write_ids(h),
            "Structs.g.cs": write_structs(h), "Native.g.cs": write_native(h)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--header", default=HEADER, help="the header (default: frusta.h)")
    ap.add_argument("--out", default=OUTPUT, help="the folder of the generated files")
    ap.add_argument("--check", action="store_true", help="write nothing; exit 1 if a file would change")
    args = ap.parse_args()
    try:
        files = generate(args.header)
    except HeaderError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    present = {n for n in os.listdir(args.out) if n.endswith(".g.cs")} if os.path.isdir(args.out) else set()
    stale = []
    for name in sorted(present - files.keys()):
        stale.append(name)
        print(f"{name}: generated by nothing any more", file=sys.stderr)
        if not args.check:
            os.remove(os.path.join(args.out, name))
    for name, text in files.items():
        path = os.path.join(args.out, name)
        old = ""
        if os.path.exists(path):
            with open(path, encoding="utf-8") as f:
                old = f.read()
        if old == text:
            continue
        stale.append(name)
        if args.check:
            sys.stdout.writelines(difflib.unified_diff(old.splitlines(True), text.splitlines(True),
                                                       f"{name} (checked in)", f"{name} (from the header)"))
        else:
            os.makedirs(args.out, exist_ok=True)
            with open(path, "w", encoding="utf-8", newline="\n") as f:
                f.write(text)
            print(f"wrote {os.path.relpath(path, ROOT)}")
    if args.check and stale:
        print(f"error: the C# interop is stale: run python3 {SELF} (and tests/dotnet/unity_meta.py for a new file)",
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
