"""folders: a run's folder: the inputs' signature (settings and template content:
a partial case of other inputs is not resumed), the files curtainCase wrote in a
case (its manifest), the swap of a finished case into DIR/case keeping the
user's files, the pruning of time folders, and atomic writes."""

import hashlib
import json
import os
import re
import shutil

from ..files import WriteError, atomic_write as write_whole
from ..errors import RunError
from .settings import MANIFEST


def atomic_write(path, text):
    try:
        write_whole(path, text)
    except WriteError as e:
        raise RunError(str(e))


def signature(s):
    """The settings and the template's content: a partial case of other inputs is
    not resumed."""
    h = hashlib.sha256()
    keys = sorted(k for k in s if k not in ("dir", "argv", "keep", "check", "np", "names", "window",
                                            "every", "end", "startFromDir"))
    h.update(json.dumps({k: s[k] for k in keys}, sort_keys=True, default=str).encode())
    for root, dirs, files in sorted(os.walk(s["template"])):
        dirs.sort()
        for f in sorted(files):
            p = os.path.join(root, f)
            h.update(os.path.relpath(p, s["template"]).encode())
            with open(p, "rb") as fh:
                h.update(fh.read())
    return h.hexdigest()


def ours(case):
    """Relative paths of the files curtainCase wrote in a finished case folder
    (its manifest; a folder of an older curtainCase: the OpenFOAM case layout)."""
    try:
        with open(os.path.join(case, MANIFEST)) as f:
            return set(json.load(f)) | {MANIFEST}
    except (OSError, ValueError):
        pass
    made = set()
    for root, dirs, files in os.walk(case):
        rel = os.path.relpath(root, case)
        top = rel.split(os.sep)[0]
        for f in files:
            name = f if rel == "." else os.path.join(rel, f)
            if rel == "." and (f.startswith("log.") or f.endswith(".foam") or f.startswith(".curtainCase")):
                made.add(name)
            elif top in ("0", "0.orig", "constant", "system", "postProcessing", "VTK") \
                    or top.startswith("processor") or re.fullmatch(r"[0-9.eE+-]+", top):
                made.add(name)
    return made


def all_files(case):
    out = set()
    for root, dirs, files in os.walk(case):
        for f in files:
            out.add(os.path.relpath(os.path.join(root, f), case))
    return out


def install_case(new, old):
    """Make the finished case `new` the case folder `old`: files of the old folder
    that curtainCase did not write move into the new one, then the swap is two
    renames. Returns the user's files kept."""
    user = []
    if os.path.isdir(old):
        mine = ours(old)
        for rel in sorted(all_files(old) - mine):
            src, dst = os.path.join(old, rel), os.path.join(new, rel)
            if os.path.exists(dst):
                dst = os.path.join(new, "kept", rel)   # the new run made one of that name
            os.makedirs(os.path.dirname(dst), exist_ok=True)
            os.replace(src, dst)
            user.append(os.path.relpath(dst, new))
        trash = old + ".old%d" % os.getpid()
        os.replace(old, trash)
        os.replace(new, old)
        remove_ours(trash, mine)
    else:
        os.replace(new, old)
    return user


def remove_ours(folder, mine):
    for rel in mine:
        try:
            os.remove(os.path.join(folder, rel))
        except OSError:
            pass
    for root, dirs, files in os.walk(folder, topdown=False):
        try:
            os.rmdir(root)
        except OSError:
            pass


def prune(s, case):
    """Without -keep: drop the time folders and the mesh of a finished case."""
    if s["keep"]:
        return
    for d in os.listdir(case):
        full = os.path.join(case, d)
        if d.startswith("processor") or (re.fullmatch(r"[0-9.eE+-]+", d) and d != "0"):
            shutil.rmtree(full, ignore_errors=True)
    shutil.rmtree(os.path.join(case, "constant", "polyMesh"), ignore_errors=True)
