"""docFigures: a figure is filled from its results file, a figure that differs
is reported, and a value that is not a finite number, a missing row or column,
a needle a test does not hold, or a figure typed by hand is an error."""

import os

import pytest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", ".."))
from flightedDryer import docFigures as df  # noqa: E402

CSV = "# a comment\nmodel,group,rms_ln,bias_ln\nshipped,all,0.3687,-0.0731\nother one,all,0.5,0.1\n"


@pytest.fixture
def tree(tmp_path):
    (tmp_path / "r.csv").write_text(CSV)
    (tmp_path / "test.sh").write_text('checkClose "x" "$x" 1 0.02\n')
    (tmp_path / "gen.py").write_text(
        "def t(results):\n"
        "    return '| a |\\n|---|\\n| %s |' % results.value('r.csv', {'model': 'shipped'}, 'rms_ln')\n")
    return tmp_path


def doc(tree, text):
    (tree / "d.md").write_text(text)
    return "d.md"


def fig(row, col, form, shown):
    return "<!--fig r.csv %s %s %s-->%s<!--/fig-->" % (row, col, form, shown)


def test_update_fills_and_check_agrees(tree):
    d = doc(tree, "error " + fig("model=shipped", "rms_ln", "%.3f", "?") + " bias "
            + fig("model=shipped", "bias_ln", "%+.2f", "?") + " pct " + fig("model=shipped", "rms_ln*100", "%.0f", "?"))
    assert df.update(str(tree), d) == 3
    text = (tree / d).read_text()
    assert ">0.369<" in text and ">\u22120.07<" in text and ">37<" in text
    assert df.check(str(tree), d) == []


def test_a_figure_that_differs_is_reported(tree):
    d = doc(tree, "line one\nerror " + fig("model=shipped", "rms_ln", "%.3f", "0.312"))
    msgs = df.check(str(tree), d)
    assert msgs == ["d.md:2: states 0.312, r.csv model=shipped rms_ln gives 0.369"]


def test_url_quoted_row_value(tree):
    d = doc(tree, fig("model=other%20one", "rms_ln", "%.1f", "?"))
    df.update(str(tree), d)
    assert ">0.5<" in (tree / d).read_text()


@pytest.mark.parametrize("bad", ["nan", "inf", "-inf", "", "text", "1e999"])
def test_a_value_that_is_not_a_finite_number_is_an_error(tree, bad):
    (tree / "r.csv").write_text("model,rms_ln\nshipped,%s\n" % bad)
    d = doc(tree, "x\n" + fig("model=shipped", "rms_ln", "%.3f", "0.369"))
    with pytest.raises(df.FigureError, match=r"d\.md:2"):
        df.check(str(tree), d)


@pytest.mark.parametrize("row,col,match", [
    ("model=missing", "rms_ln", "0 rows"), ("group=all", "rms_ln", "2 rows"), ("-", "rms_ln", "match"),
    ("model=shipped", "nocolumn", "no column"), ("modelshipped", "rms_ln", "not column=value")])
def test_a_missing_or_ambiguous_row_or_column_is_an_error(tree, row, col, match):
    d = doc(tree, fig(row, col, "%.3f", "1"))
    with pytest.raises(df.FigureError, match=match):
        df.check(str(tree), d)


def test_a_missing_file_is_an_error(tree):
    d = doc(tree, "<!--fig gone.csv - x %.1f-->1<!--/fig-->")
    with pytest.raises(df.FigureError, match="cannot read gone.csv"):
        df.check(str(tree), d)


def test_a_table_is_generated_and_a_stale_one_reported(tree):
    d = doc(tree, "before\n<!--table gen.py:t-->\n| stale |\n<!--/table-->\nafter")
    assert df.check(str(tree), d) == ["d.md:2: table gen.py:t differs from what its results give (run docs/figures -update)"]
    df.update(str(tree), d)
    assert (tree / d).read_text() == "before\n<!--table gen.py:t-->\n| a |\n|---|\n| 0.3687 |\n<!--/table-->\nafter"
    assert df.check(str(tree), d) == []


def test_a_table_without_its_end_or_generator_is_an_error(tree):
    with pytest.raises(df.FigureError, match="without"):
        df.check(str(tree), doc(tree, "<!--table gen.py:t-->\n| x |\n"))
    with pytest.raises(df.FigureError, match="no table function"):
        df.check(str(tree), doc(tree, "<!--table gen.py:nothere-->\n<!--/table-->"))


def test_a_tested_bound_must_be_in_its_test(tree):
    assert df.check(str(tree), doc(tree, "within <!--in test.sh 1%200.02-->2 %<!--/in-->")) == []
    with pytest.raises(df.FigureError, match="does not hold '1 0.03'"):
        df.check(str(tree), doc(tree, "within <!--in test.sh 1%200.03-->3 %<!--/in-->"))


def test_unmarked_finds_figures_typed_by_hand(tree):
    d = doc(tree, "\n".join([
        "scores 0.312 and 62 % within, 7x faster, in 22 s",          # four figures
        "a 6.6 m fall at 4 m/s, 1.4–8.6 m/s, 850 um, Eq 14.2, Tables 7.3 and 7.5",   # inputs, references
        "goal: RMS ln ≤ 0.28, bias within ±0.10",                     # thresholds
        "marked " + fig("model=shipped", "rms_ln", "%.3f", "0.369") + " `code 0.5`",
        "```", "0.123 in a code block", "```"]))
    found = [(n, v) for n, v, _ in df.unmarked(str(tree), d)]
    assert found == [(1, "0.312"), (1, "62"), (1, "7"), (1, "22")]


def test_negative_zero_has_no_sign():
    assert df.fmt(-0.0001, "%+.2f") == "0.00"
    assert df.fmt(-0.01, "%.2f") == "\u22120.01"


def test_a_marker_in_a_code_span_is_an_example(tree):
    d = doc(tree, "write `<!--fig r.csv model=none rms_ln %.3f-->1<!--/fig-->` or `<!--in TEST X-->`")
    assert df.check(str(tree), d) == []
