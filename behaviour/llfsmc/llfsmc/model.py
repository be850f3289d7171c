"""The parsed model: what the checks look at and the emitters print."""

from . import syntax as S

ACTIONS = ("OnEntry", "OnExit", "Internal", "OnSuspend", "OnResume")
ACCESS = ("read", "write", "readwrite")


class Var:
    """external (type: whiteboard message name, access), local (type: syntax.Type, init: syntax
    tree) or parameter (type: syntax.Type)."""

    def __init__(self, kind, name, type_, pos, access=None, init=None):
        self.kind, self.name, self.type, self.pos = kind, name, type_, pos
        self.access, self.init = access, init

    @property
    def line(self):
        return self.pos[0]

    @property
    def member(self):
        return {"external": "x_", "local": "l_", "parameter": "p_"}[self.kind] + self.name + "_"

    @property
    def cxx_type(self):
        """The declared C++ type (externals: the whiteboard type, fully qualified)."""
        if self.kind == "external":
            return "::ringlet::wb::" + self.type
        return S.print_type(self.type)

    @property
    def value_type(self):
        """The C++ type the action code sees (a reference parameter's referred-to type)."""
        if self.kind == "external":
            return self.cxx_type
        return S.print_type(self.type.without_ref())


class Transition:
    def __init__(self, target, target_pos, guard, pos):
        self.target, self.target_pos, self.guard, self.pos = target, target_pos, guard, pos

    @property
    def line(self):
        return self.pos[0]


class Action:
    def __init__(self, first_line, code, tokens):
        self.first_line, self.code, self.tokens = first_line, code, tokens


class State:
    def __init__(self, name, pos, initial):
        self.name, self.pos, self.initial = name, pos, initial
        self.actions = {}  # section -> Action
        self.transitions = []
        self.submachine = None  # (machine, mode, pos)
        self.reads, self.writes = [], []

    @property
    def line(self):
        return self.pos[0]


class Assume:
    """A verification declaration (behaviour/README.md, "Model checking"): kind "domain"
    (`assume x.f in {a, b}`: the values an input or an abstracted variable may take), "value"
    (`assume p = v`: a parameter's value in the verification) or "call" (`assume call ns::f in
    {a, b}`: what an abstracted library call may return)."""

    def __init__(self, kind, target, values, pos):
        self.kind, self.target, self.values, self.pos = kind, target, values, pos


class Property:
    """`ltl name: formula` (kind "ltl") or `assert name: expression` (kind "assert", checked at the
    end of every turn)."""

    def __init__(self, kind, name, tree, pos):
        self.kind, self.name, self.tree, self.pos = kind, name, tree, pos


class Model:
    def __init__(self):
        self.name = None
        self.name_pos = (1, 1)
        self.includes = []
        self.variables = {}  # name -> Var, declaration order kept
        self.states = []
        self.source_name = ""
        self.assumes = []  # Assume, in order
        self.properties = []  # Property, in order
