"""The whiteboard schema's reader. It lives beside the schema it reads
(whiteboard/schema/ringlet_schema.py), so that every generator (llfsmc here, the DDS IDL in remote/)
reads schema.def the same way."""

import os
import sys

_READER_DIR = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                            "whiteboard", "schema"))
if _READER_DIR not in sys.path:
    sys.path.insert(0, _READER_DIR)

from ringlet_schema import SCALARS, Schema, parse_schema  # noqa: E402,F401
