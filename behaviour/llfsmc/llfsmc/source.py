"""Reading the inputs: bounded (regular files only, a size limit) and strictly UTF-8, every
failure a FileProblem naming the file and, where there is one, the position."""

import os
import stat

MAX_MODEL_BYTES = 1 << 20
MAX_SCHEMA_BYTES = 1 << 20


class FileProblem(Exception):
    def __init__(self, message, line=None, col=None):
        super().__init__(message)
        self.message, self.line, self.col = message, line, col


def read_text(path, what, max_bytes):
    """The file's text (UTF-8, a leading byte order mark dropped)."""
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0))
    except OSError as exc:
        raise FileProblem(f"cannot read {what}: {exc.strerror or exc}")
    try:
        st = os.fstat(fd)
        if stat.S_ISDIR(st.st_mode):
            raise FileProblem(f"cannot read {what}: is a directory")
        if not stat.S_ISREG(st.st_mode):
            raise FileProblem(f"cannot read {what}: not a regular file")
        if st.st_size > max_bytes:
            raise FileProblem(f"cannot read {what}: larger than {max_bytes} bytes")
        chunks, total = [], 0
        while True:
            chunk = os.read(fd, 65536)
            if not chunk:
                break
            total += len(chunk)
            if total > max_bytes:
                raise FileProblem(f"cannot read {what}: larger than {max_bytes} bytes")
            chunks.append(chunk)
    except OSError as exc:
        raise FileProblem(f"cannot read {what}: {exc.strerror or exc}")
    finally:
        os.close(fd)
    data = b"".join(chunks)
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        line_start = data.rfind(b"\n", 0, exc.start) + 1
        col = len(data[line_start:exc.start].decode("utf-8", "replace")) + 1
        raise FileProblem(f"invalid UTF-8 (byte 0x{data[exc.start]:02x}): a {what} is UTF-8 text", line, col)
    return text[1:] if text.startswith("\ufeff") else text


def write_text(path, text):
    """Writes through a temporary file in the same directory and renames it over `path`, so that a
    failed write leaves the old output, not half a file. Always writes: the build compares the
    output's time with the model's."""
    directory = os.path.dirname(os.path.abspath(path))
    tmp = os.path.join(directory, f".{os.path.basename(path)}.{os.getpid()}.tmp")
    try:
        os.makedirs(directory, exist_ok=True)
        with open(tmp, "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
        os.replace(tmp, path)
    except OSError as exc:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise FileProblem(f"cannot write output: {exc.strerror or exc}")
