#!/usr/bin/env python3
"""wb_idl: writes the OMG IDL for every whiteboard message type, from schema.def, for Cyclone DDS's
idlc (and for anyone's own DDS tools: the file is installed).

  wb_idl.py SCHEMA_DEF OUT_IDL

Naming follows ROS 2's mapping of messages to DDS, so that ROS 2 tools on the same network see the
topics: message Name becomes struct ringlet::msg::dds_::Name_ (topic "rt/ringlet/<snake_name>",
see remote/README.md). Every struct starts with two fields the bridge fills in:
  robot       @key: which robot posted it (the firmware's robot id), so one monitor tells robots apart
  generation  the whiteboard generation of this message (1, 2, ...): gaps show what was not sent
FsmStatus and FsmControl are keyed by machine too, so that a late joiner sees every machine's state
(one instance per robot and machine). Enumerators are prefixed with their enum's name: IDL puts
them in the enclosing module's scope, where two enums could otherwise clash.

Standard library only: it runs on the build host, also in the cross build."""

import os
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                                 "whiteboard", "schema")))
from ringlet_schema import parse_schema  # noqa: E402

# Extra key fields beyond the robot id, per message type.
EXTRA_KEYS = {"FsmStatus": ["machine"], "FsmControl": ["machine"]}

SCALAR_IDL = {
    "bool": "boolean",
    "double": "double",
    "float": "float",
    "std::int8_t": "int8",
    "std::int16_t": "short",
    "std::int32_t": "long",
    "std::int64_t": "long long",
    "std::uint8_t": "octet",
    "std::uint16_t": "unsigned short",
    "std::uint32_t": "unsigned long",
    "std::uint64_t": "unsigned long long",
}


# IDL 4.2's keywords. An identifier equal to one, ignoring case, is escaped with a leading
# underscore, which IDL strips again: the C field keeps the schema's name ("sequence").
IDL_KEYWORDS = {k.lower() for k in """
    abstract any alias attribute bitfield bitmask bitset boolean case char component connector const
    consumes context custom default double exception emits enum eventtype factory false finder fixed
    float getraises getter home import in inout interface local long manages map mirrorport module
    multiple native object octet oneway out primarykey private port porttype provides public
    publishes raises readonly setraises setter sequence short string struct supports switch true
    truncatable typedef typeid typename typeprefix unsigned union uses valuebase valuetype void wchar
    wstring int8 uint8 int16 int32 int64 uint16 uint32 uint64""".split()}


def idl_name(name):
    return "_" + name if name.lower() in IDL_KEYWORDS else name


class SchemaError(Exception):
    pass


def idl_type(schema, ctype, where):
    """(IDL type, array suffix) of a schema field type."""
    ctype = ctype.strip()
    if ctype in SCALAR_IDL:
        return SCALAR_IDL[ctype], ""
    if ctype in schema.enums:
        return ctype, ""
    if ctype.startswith("FixedString<") and ctype.endswith(">"):
        return f"string<{int(ctype[len('FixedString<'):-1])}>", ""
    if ctype.startswith("std::array<") and ctype.endswith(">"):
        inner = ctype[len("std::array<"):-1]
        element, count = inner.rsplit(",", 1)
        base, suffix = idl_type(schema, element, where)
        if suffix:
            raise SchemaError(f"{where}: arrays of arrays have no IDL mapping here")
        return base, f"[{int(count)}]"
    raise SchemaError(f"{where}: field type '{ctype}' has no IDL mapping (add it to remote/idl/wb_idl.py)")


def generate(schema, source_name):
    out = [f"// Generated from {source_name} by remote/idl/wb_idl.py: do not edit.",
           "// The whiteboard's message types as DDS topics (remote/README.md).",
           "module ringlet {", "module msg {", "module dds_ {", ""]
    for name, enumerators in schema.enums.items():
        out.append(f"enum {name} {{ " + ", ".join(f"{name}_{e}" for e in enumerators) + " };")
    out.append("")
    for name, fields in schema.messages.items():
        keys = EXTRA_KEYS.get(name, [])
        for k in keys:
            if k not in fields:
                raise SchemaError(f"{name}: key field '{k}' is not in schema.def")
        out.append(f"// whiteboard type id {schema.ids[name]}")
        out.append(f"struct {name}_ {{")
        out.append("  @key unsigned short robot;")
        out.append("  unsigned long long generation;")
        for field, ctype in fields.items():
            base, suffix = idl_type(schema, ctype, f"{name}.{field}")
            key = "@key " if field in keys else ""
            out.append(f"  {key}{base} {idl_name(field)}{suffix};")
        out.append("};")
        out.append("")
    out += ["};", "};", "};", ""]
    return "\n".join(out)


def main(argv):
    if len(argv) != 3 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) == 2 and argv[1] in ("-h", "--help") else 2
    schema_path, out_path = argv[1], argv[2]
    try:
        with open(schema_path, encoding="utf-8") as f:
            text = f.read()
    except OSError as e:
        print(f"wb_idl: cannot read the schema {schema_path}: {e.strerror}", file=sys.stderr)
        return 2
    try:
        schema = parse_schema(text)
        idl = generate(schema, os.path.basename(schema_path))
    except ValueError as e:
        line, message = e.args if len(e.args) == 2 else ("?", str(e))
        print(f"{schema_path}:{line}: {message}", file=sys.stderr)
        return 2
    except SchemaError as e:
        print(f"{schema_path}: {e}", file=sys.stderr)
        return 2
    # Write only when changed: idlc and the C compiler then rerun only when the types change.
    try:
        with open(out_path, encoding="utf-8") as f:
            if f.read() == idl:
                return 0
    except OSError:
        pass
    tmp = out_path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(idl)
    os.replace(tmp, out_path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
