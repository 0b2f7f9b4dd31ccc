"""strictDict: a dictionary's keywords scanned with their lines; a keyword given
twice, an unbalanced bracket, a directive or an unknown entry is refused naming
the file, the line and the entry; values are checked against their ranges."""

import pytest

from flightedDryer.errors import InputError
from flightedDryer.strictDict import StrictDict, check_allowed, scan_keys

HEAD = "FoamFile { version 2.0; format ascii; class dictionary; object d; }\n"


def test_keys_with_their_lines():
    top = scan_keys("d", HEAD + "a 1;\n// b 2;\n/* c\n 3; */\ngrid\n{\n    x (1 2);\n    y 3;\n}\n")
    assert top["a"] == (2, {})
    assert top["grid"] == (6, {"x": 8, "y": 9})
    assert "b" not in top and "c" not in top


@pytest.mark.parametrize("text,match", [
    ("a 1;\na 2;\n", r"d:3: entry 'a' given twice \(first on line 2\)"),
    ("grid { x 1; x 2; }\n", r"entry 'grid/x' given twice"),
    ("a (1 2;\n", r"d:2: '\(' is never closed"),
    ("a 1);\n", r"unbalanced '\)'"),
    ("#include \"other\"\n", r"directive #include is not supported"),
    ("a \"open;\n", r"string is never closed"),
    ("/* never closed\n", r"comment '/\*' is never closed"),
])
def test_malformed_dictionaries_are_refused_with_the_line(text, match):
    with pytest.raises(InputError, match=match):
        scan_keys("d", HEAD + text)


def test_unknown_entries_name_the_nearest_allowed():
    top = scan_keys("d", HEAD + "gasVelocty 1;\n")
    with pytest.raises(InputError, match=r"d:2: unknown entry 'gasVelocty' \(did you mean 'gasVelocity'\?\)"):
        check_allowed("d", top, ("FoamFile", "gasVelocity", "grid"), ("x",), "grid")
    top = scan_keys("d", HEAD + "grid { xx 1; }\n")
    with pytest.raises(InputError, match=r"unknown entry 'grid/xx' \(did you mean 'grid/x'\?\); allowed \(s\): x"):
        check_allowed("d", top, ("FoamFile", "grid"), ("x",), "grid", sub_note=" (s)")


def test_values_are_checked_against_their_ranges(tmp_path):
    p = tmp_path / "dict"
    p.write_text(HEAD + "v 3;\nw 1e9;\nlist (1 2 2);\nn 7;\nword two words;\n")
    d = StrictDict(str(p))
    assert d.scalar("v", 0, 5) == 3.0
    with pytest.raises(InputError, match=r"dict:3: entry 'w' = '1e\+09' outside the allowed range \[0, 10\] m"):
        d.scalar("w", 0, 10, "m")
    with pytest.raises(InputError, match=r"entry 'list' = .* must be strictly increasing"):
        d.scalar_list("list", 0, 10, "m")
    with pytest.raises(InputError, match=r"a multiple of 3"):
        d.whole("n", 1, 10, multiple=3)
    with pytest.raises(InputError, match=r"is not a single word"):
        d.word("word")
    assert d.whole("missing", 1, 10) is None


def test_a_file_that_is_not_text_is_refused(tmp_path):
    p = tmp_path / "dict"
    p.write_bytes(HEAD.encode() + b"a \xff;\n")
    with pytest.raises(InputError, match=r"line 2, byte 3 \(0xff\) is not UTF-8 text"):
        StrictDict(str(p))
