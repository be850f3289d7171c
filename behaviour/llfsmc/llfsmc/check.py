"""The semantic rules, after parsing: states and transitions, whiteboard types, and guards and
initial values against the declarations (behaviour/README.md, "What is checked").

What a guard may name:
  * an unqualified name must be a declared variable (external, local, parameter);
  * `.field` on an external (or on a local/parameter of a ringlet::wb:: message type) must be a
    field of that message in the schema; fields of scalar type have no fields and cannot be
    indexed, std::array fields can only be indexed;
  * `.field` on a fundamental-typed variable is refused; on other class types (from included
    headers) it cannot be known here and is left to the C++ compiler;
  * ::-qualified names are constants from headers; ringlet::wb::<SchemaEnum>::<kValue> is checked
    against the schema, anything else is left to the C++ compiler.
"""

from . import syntax as S
from .lexer import free_identifiers

# Named types that are scalars (no fields, no index): std:: integer typedefs.
STD_SCALARS = {("std", n) for n in (
    "size_t", "ptrdiff_t", "int8_t", "int16_t", "int32_t", "int64_t", "uint8_t", "uint16_t",
    "uint32_t", "uint64_t", "intptr_t", "uintptr_t")}


def check_model(model, schema, diags):
    names = {s.name for s in model.states}
    initials = [s for s in model.states if s.initial]
    if not model.states:
        diags.error(*model.name_pos, f"machine '{model.name}' has no states")
    elif not initials:
        diags.error(*model.name_pos, f"machine '{model.name}' has no initial state (mark one 'state <Name> initial')")
    for extra in initials[1:]:
        diags.error(*extra.pos, f"second initial state '{extra.name}' (first is '{initials[0].name}')")
    for v in model.variables.values():
        check_variable(v, schema, diags)
    for s in model.states:
        if s.submachine and s.submachine[0] == model.name:
            diags.error(*s.submachine[2], f"machine '{model.name}' cannot be its own submachine")
        for t in s.transitions:
            if t.target not in names:
                diags.error(*t.target_pos, f"unknown state '{t.target}' in transition from '{s.name}'")
            ExprChecker(model, schema, diags, "guard").check(t.guard)


def check_variable(v, schema, diags):
    if v.kind == "external":
        if v.type not in schema.messages:
            diags.error(*v.type_pos, f"unknown whiteboard type '{v.type}' for external '{v.name}' (not a message type in schema.def)")
        return
    for t in _types_in(v.type):
        if t.kind == "named" and t.parts[:2] == ("ringlet", "wb") and len(t.parts) == 3:
            if t.parts[2] not in schema.messages and t.parts[2] not in schema.enums:
                diags.error(*t.pos, f"unknown whiteboard type '{t.parts[2]}' (not in schema.def)")
    if v.kind == "local":
        ExprChecker(None, schema, diags, "initial value").check(v.init)


def _types_in(t):
    while t is not None:
        yield t
        t = t.element if t.kind == "array" else None


class ExprChecker:
    """Checks one guard (model given) or initial value (model None: no variables in scope)."""

    def __init__(self, model, schema, diags, what):
        self.model, self.schema, self.diags, self.what = model, schema, diags, what

    def check(self, tree):
        for node in S.walk(tree):
            problem = self.problem(node)
            if problem:
                self.diags.error(*problem)
                return False
        return True

    def problem(self, node):
        if isinstance(node, S.NumberLit) and node.kind == "duration" and self.model is None:
            return (*node.pos, f"chrono literals ('{node.text}') are only available in guards")
        if isinstance(node, S.Name):
            return self.name_problem(node)
        if isinstance(node, (S.Member, S.Index)):
            return self.access_problem(node)
        return None

    def name_problem(self, node):
        if len(node.parts) == 1 and not node.rooted:
            if self.model is None:
                return (*node.pos, f"initial values may only use literals and ::-qualified constants, not '{node.parts[0]}'")
            if node.parts[0] not in self.model.variables:
                return (*node.pos, f"undeclared variable '{node.parts[0]}' in {self.what}")
            return None
        if node.parts[:2] == ("ringlet", "wb") and len(node.parts) == 4 and node.parts[2] in self.schema.enums:
            if node.parts[3] not in self.schema.enums[node.parts[2]]:
                return (*node.pos, f"'{node.parts[3]}' is not an enumerator of {node.parts[2]} "
                                   f"({', '.join(self.schema.enums[node.parts[2]])})")
        return None

    def shape(self, node):
        """What is known about a node's type: ("message", name), ("scalar", text), ("array", elem
        shape), or None when it cannot be known here."""
        if isinstance(node, S.Paren):
            return self.shape(node.expr)
        if isinstance(node, S.Name) and len(node.parts) == 1 and self.model is not None:
            v = self.model.variables.get(node.parts[0])
            if v is None:
                return None
            if v.kind == "external":
                return ("message", v.type)
            return self.type_shape(v.type)
        if isinstance(node, S.Member):
            obj = self.shape(node.obj)
            if obj is not None and obj[0] == "message":
                ftype = self.schema.messages.get(obj[1], {}).get(node.field)
                return None if ftype is None else self.field_shape(ftype)
            return None
        if isinstance(node, S.Index):
            obj = self.shape(node.obj)
            return obj[1] if obj is not None and obj[0] == "array" else None
        return None

    def field_shape(self, ftype):
        kind = self.schema.field_kind(ftype)
        if kind in ("scalar", "enum"):
            return ("scalar", ftype)
        if kind == "array":
            return ("array", self.field_shape(self.schema.array_element(ftype)))
        return None

    def type_shape(self, t):
        if t.kind == "fundamental":
            return ("scalar", " ".join(t.words))
        if t.kind == "array":
            return ("array", self.type_shape(t.element))
        if t.parts in STD_SCALARS:
            return ("scalar", "::".join(t.parts))
        if t.parts[:2] == ("ringlet", "wb") and len(t.parts) == 3 and t.parts[2] in self.schema.messages:
            return ("message", t.parts[2])
        return None

    def access_problem(self, node):
        obj = self.shape(node.obj)
        if obj is None:
            return None
        what = S.print_expr(node.obj)
        if isinstance(node, S.Member):
            if obj[0] == "message":
                fields = self.schema.messages.get(obj[1], {})
                if node.field not in fields:
                    return (*node.pos, f"'{what}' ({obj[1]}) has no field '{node.field}' (fields: {', '.join(fields)})")
                return None
            if obj[0] == "scalar":
                return (*node.pos, f"'{what}' is a {obj[1]}: it has no field '{node.field}'")
            return (*node.pos, f"'{what}' is a std::array: it has no field '{node.field}' (index it with [])")
        if obj[0] != "array":
            return (*node.pos, f"'{what}' is not an array: it cannot be indexed")
        return None


def guard_variables(model, guard):
    """The declared variables a guard mentions (unqualified names)."""
    return {n.parts[0] for n in S.walk(guard)
            if isinstance(n, S.Name) and len(n.parts) == 1 and not n.rooted and n.parts[0] in model.variables}


def footprints(model):
    """READ/WRITE footprint of every state: the externals its code and guards mention."""
    for s in model.states:
        used = set()
        for action in s.actions.values():
            used.update(free_identifiers(action.tokens))
        for t in s.transitions:
            used |= guard_variables(model, t.guard)
        for v in model.variables.values():
            if v.kind == "external" and v.name in used:
                if v.access in ("read", "readwrite"):
                    s.reads.append(v)
                if v.access in ("write", "readwrite"):
                    s.writes.append(v)
