"""Reads the whiteboard schema (whiteboard/include/ringlet/whiteboard/schema.def) for the code
generators that run on the build host (Python, standard library only): which message types exist
(with their ids), their fields and field types, and the schema enums. The C++ side reads the same
file through its X-macros; this reader is the one for everything else (llfsmc checks models
against it, remote/ generates the DDS IDL from it)."""

SCALARS = {"bool", "double", "float", "std::int8_t", "std::int16_t", "std::int32_t", "std::int64_t",
           "std::uint8_t", "std::uint16_t", "std::uint32_t", "std::uint64_t"}


class Schema:
    def __init__(self):
        self.messages = {}  # name -> {field: C++ type text}, declaration order kept
        self.ids = {}  # message name -> its stable id
        self.enums = {}  # name -> [enumerators]

    def field_kind(self, type_text):
        """scalar (no members, no index), array (index only), enum, or opaque (FixedString...)."""
        if type_text in SCALARS:
            return "scalar"
        if type_text in self.enums:
            return "enum"
        if type_text.startswith("std::array<"):
            return "array"
        return "opaque"

    @staticmethod
    def array_element(type_text):
        """`std::array<T, N>` -> T (the schema's arrays are of scalars and enums)."""
        inner = type_text[len("std::array<"):type_text.rindex(">")]
        return inner[:inner.rindex(",")].strip()


def _arguments(line, macro):
    """The comma-separated arguments of `MACRO(a, b, c...)` (the last may contain commas)."""
    inner = line[len(macro) + 1:line.rindex(")")]
    return [a.strip() for a in inner.split(",", 1)]


def parse_schema(text):
    """Reads the X-macro lines; raises ValueError(line, message) on a line it cannot read."""
    schema = Schema()
    current = None
    for number, raw in enumerate(text.split("\n"), 1):
        line = raw.split("//", 1)[0].strip()
        if not line.startswith("WB_") or line.startswith("#"):
            continue
        try:
            if line.startswith("WB_MESSAGE_BEGIN("):
                current, rest = _arguments(line, "WB_MESSAGE_BEGIN")
                schema.messages[current] = {}
                schema.ids[current] = int(rest.split(",", 1)[0])
            elif line.startswith("WB_FIELD(") and current is not None:
                name, ftype = _arguments(line, "WB_FIELD")
                schema.messages[current][name] = ftype
            elif line.startswith("WB_MESSAGE_END("):
                current = None
            elif line.startswith("WB_ENUM_BEGIN("):
                schema.enums[_arguments(line, "WB_ENUM_BEGIN")[0]] = []
            elif line.startswith("WB_ENUMERATOR("):
                enum, rest = _arguments(line, "WB_ENUMERATOR")
                schema.enums.setdefault(enum, []).append(rest.split(",", 1)[0].strip())
        except ValueError:
            raise ValueError(number, f"cannot read '{line}'")
    return schema
