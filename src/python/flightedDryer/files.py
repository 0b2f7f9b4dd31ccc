"""dryerFiles: the one way the project's Python tools write files.

Every output is written whole or not at all: into a temporary file beside the
target, flushed to disk and checked complete (the byte count; a PNG's end
chunk), then renamed over the target. On any error (a full disk, a missing
folder, no permission) the temporary is removed and WriteError names the file.
"""

import os

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
PNG_END = b"IEND\xaeB`\x82"


class WriteError(Exception):
    """An output that could not be written completely."""


def _temporary(path):
    d = os.path.dirname(os.path.abspath(path))
    return os.path.join(d, "." + os.path.basename(path) + ".tmp%d" % os.getpid())


def _discard(tmp):
    try:
        os.remove(tmp)
    except OSError:
        pass


def atomic_write(path, data):
    """Write text (str, UTF-8) or bytes to `path` atomically."""
    if isinstance(data, str):
        data = data.encode("utf-8")
    tmp = _temporary(path)
    try:
        with open(tmp, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        if os.path.getsize(tmp) != len(data):
            raise OSError(5, "short write (%d of %d bytes)" % (os.path.getsize(tmp), len(data)))
        os.replace(tmp, path)
    except OSError as e:
        _discard(tmp)
        raise WriteError("cannot write %s: %s" % (path, e.strerror or e))


def png_complete(path):
    """A PNG file that starts with the signature and ends with its IEND chunk."""
    try:
        size = os.path.getsize(path)
        with open(path, "rb") as f:
            head = f.read(8)
            f.seek(max(0, size - 8))
            tail = f.read(8)
    except OSError:
        return False
    return head == PNG_SIGNATURE and tail == PNG_END


def save_figure(fig, path, dpi):
    """A matplotlib figure to a PNG, atomically and checked complete."""
    tmp = _temporary(path)
    try:
        fig.savefig(tmp, dpi=dpi, format="png")
        with open(tmp, "rb+") as f:
            os.fsync(f.fileno())
        if not png_complete(tmp):
            raise OSError(5, "incomplete PNG")
        os.replace(tmp, path)
    except (OSError, ValueError) as e:
        _discard(tmp)
        raise WriteError("cannot write %s: %s" % (path, getattr(e, "strerror", None) or e))
