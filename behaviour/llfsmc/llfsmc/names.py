"""What may name a machine, a state, a variable: C++ identifiers that are not keywords, not
reserved for the implementation, and not already used by the generated class."""

# C++20 keywords and alternative tokens.
CXX_KEYWORDS = frozenset("""
alignas alignof and and_eq asm auto bitand bitor bool break case catch char char8_t char16_t
char32_t class compl concept const consteval constexpr constinit const_cast continue co_await
co_return co_yield decltype default delete do double dynamic_cast else enum explicit export extern
false float for friend goto if inline int long mutable namespace new noexcept not not_eq nullptr
operator or or_eq private protected public register reinterpret_cast requires return short signed
sizeof static static_assert static_cast struct switch template this thread_local throw true try
typedef typeid typename union unsigned using virtual void volatile wchar_t while xor xor_eq
""".split())
# Identifiers with a special meaning in some contexts: legal names, but confusing ones.
CXX_SPECIAL = frozenset({"final", "override", "import", "module"})

# Names the generated class or its Machine base already uses: a variable with one of these names
# would hide it inside action code; `std` and `ringlet` would hide the namespaces.
RUNTIME_RESERVED = frozenset({
    "after", "after_ms", "now", "name", "state_time", "ringlets", "suspended", "request",
    "suspend_machine", "resume_machine", "restart_machine", "current_state", "current_state_name",
    "state_count", "state_name", "wb_", "wb", "s", "std", "ringlet",
})

# FsmStatus and FsmControl carry machine and state names in FixedString<32>.
MAX_NAME_LENGTH = 32


def identifier_problem(name):
    """Why `name` cannot be used as a C++ name, or None."""
    if not name or not (name[0].isascii() and (name[0].isalpha() or name[0] == "_")) or \
            not all(c.isascii() and (c.isalnum() or c == "_") for c in name):
        return f"'{name}' is not a C++ identifier"
    if name in CXX_KEYWORDS:
        return f"'{name}' is a C++ keyword"
    if name in CXX_SPECIAL:
        return f"'{name}' has a special meaning in C++"
    if "__" in name or (name[0] == "_" and len(name) > 1 and name[1].isupper()):
        return f"'{name}' is reserved for the C++ implementation (double underscore or _Capital)"
    return None
