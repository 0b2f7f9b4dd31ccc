"""dictionaries: the template's and the case's OpenFOAM dictionaries read and set
through flightedDryer.foamDictionary, a failure mapped to the run's kind of error
(reading the template: bad input; setting the case: a failed run)."""

import os

from .. import foamDictionary
from ..errors import InputError, RunError


def value(path, entry):
    """Value of an entry of an OpenFOAM dictionary (foamDictionary.value)."""
    try:
        return foamDictionary.value(path, entry)
    except foamDictionary.FoamDictionaryError as e:
        raise InputError(str(e))


def scalar(path, entry):
    try:
        return foamDictionary.scalar(path, entry)
    except foamDictionary.FoamDictionaryError as e:
        raise InputError(str(e))


def keywords(path, entry=None):
    """Keywords of a dictionary or sub-dictionary; none if it has none."""
    try:
        rc, out, _ = foamDictionary.run((["-entry", entry] if entry else []) + ["-keywords"], path, entry)
    except foamDictionary.FoamDictionaryError as e:
        raise InputError(str(e))
    return out.split() if rc == 0 else []


def has(path, entry):
    if not os.path.exists(path):
        return False
    try:
        return foamDictionary.has(path, entry)
    except foamDictionary.FoamDictionaryError as e:
        raise InputError(str(e))


def set_entry(path, entry, value):
    try:
        foamDictionary.set_value(path, entry, value)
    except foamDictionary.FoamDictionaryError as e:
        raise RunError(str(e))
