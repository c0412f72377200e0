"""drape's version as PEP 440 (https://peps.python.org/pep-0440/), from the text `drape --version`
and `_drape.version()` give: the project version of CMakeLists.txt, then `git describe --always
--dirty` of the sources the build came from, if it was built from a git clone:

    "0.1"                         -> "0.1"
    "0.1 (git 407930e)"           -> "0.1+g407930e"
    "0.1 (git 407930e-dirty)"     -> "0.1+g407930e.dirty"
    "0.1 (git v0.1-3-g407930e)"   -> "0.1+3.g407930e"    (3 commits after the tag v0.1)
    "0.1 (git v0.1)"              -> "0.1"               (the tagged commit itself)

The commit goes into the local segment (after `+`), which pip and packaging compare but an index
refuses: a build from a clone names its commit, a release does not. setup.py uses the same
function for the installed package's metadata, so `pip show drape` and `drape.__version__` agree.
Pure Python, no imports beyond `re`: setup.py loads this file by path, before `_drape` exists.
"""

import re

__all__ = ["pep440_version"]

_RELEASE = re.compile(r"[0-9]+(\.[0-9]+)*")
# `git describe --always --dirty`: TAG-DISTANCE-gHASH after a tag, TAG on it, HASH without one;
# each may end in -dirty (tracked files changed).
_AFTER_TAG = re.compile(r"(?P<tag>.+)-(?P<distance>[0-9]+)-g(?P<hash>[0-9a-f]{4,40})")
_HASH = re.compile(r"[0-9a-f]{4,40}")


def pep440_version(text: str) -> str:
    """The PEP 440 version of a drape version text ("0.1 (git 407930e-dirty)" -> "0.1+g407930e.dirty").

    Raises ValueError if the text does not start with a release number (digits and dots)."""
    text = text.strip()
    match = re.fullmatch(r"(?P<release>\S+)(?:\s+\(git\s+(?P<describe>[^)]*)\))?", text)
    if not match or not _RELEASE.fullmatch(match["release"]):
        raise ValueError(f"not a drape version (expected e.g. '0.1 (git 407930e)'): {text!r}")
    release = match["release"]
    describe = (match["describe"] or "").strip()
    local = []
    if describe.endswith("-dirty"):
        describe = describe[:-len("-dirty")]
        dirty = True
    else:
        dirty = False
    after_tag = _AFTER_TAG.fullmatch(describe)
    if after_tag:
        local += [after_tag["distance"], "g" + after_tag["hash"]]
    elif _HASH.fullmatch(describe):
        local.append("g" + describe)
    # Otherwise a tag alone (or nothing): the tagged commit, named by the release number.
    if dirty:
        local.append("dirty")
    return release + ("+" + ".".join(local) if local else "")
