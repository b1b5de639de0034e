# SPDX-License-Identifier: MIT
"""The planner's reader and words on hostile input: a record near
the 1 MiB limit read in linear time, a record too long skipped to its own end
(never resumed inside its quotes) and reported at the line where it began,
numbers in decimal only, a byte-order mark only at the start of the file, and
the sky words of --help, of docs/planner.md and of the library's header the
same as the words the planner accepts."""
import re
import resource
import subprocess

import pytest

from _oi_plan import PLAN, ROOT, run
from test_planner import AU, LIT, parse, run_csv, table

HEAD = "id,sun_x,sun_y,sun_z,target_x,target_y,target_z\n"
GOOD = f"ok,{AU},0,0,0,7000,0\n"
LIMIT = (1 << 20) + 16  # the reader's record buffer (CSV_MAX_RECORD + 16)


def _cpu_seconds(data):
    """oi-plan --csv - on data: (return code, stdout, child CPU seconds)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run([str(PLAN), "--csv", "-"], input=data, capture_output=True, timeout=60)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return p.returncode, p.stdout.decode(), cpu


def test_record_of_a_mebibyte_is_read_in_linear_time():
    """An id of 1 MiB less a little (a record longer than the 64 KiB read
    block): planned with the next row in well under a second (the reader
    rescanned the rest of its block per byte: about a second to five)."""
    big = "A" * ((1 << 20) - 200)
    code, out, cpu = _cpu_seconds((HEAD + big + GOOD[2:] + GOOD).encode())
    assert code == 0
    lines = out.splitlines()
    assert len(lines) == 3
    assert lines[1].startswith(big + ",OK,") and lines[2].startswith("ok,OK,")
    assert cpu < 0.4, f"{cpu:.2f} s of CPU"


def test_quoted_field_at_the_record_limit_resumes_after_the_record():
    """A quoted id that reaches the record limit exactly at a line break inside
    its quotes: one failed row named by the line where it began, then the next
    record (the reader resumed inside the quotes: four rows for two records,
    the error at the wrong line)."""
    rec = '"' + "x" * LIMIT + '\nstill,"" quoted\n' + f'",{AU},0,0,0,7000,0\n'
    code, out, err = run_csv(HEAD + rec + GOOD)
    assert code == 1
    rows = parse(out)
    assert [r["status"] for r in rows] == ["ERR_PARSE", "OK"]
    assert [r["id"] for r in rows] == ["", "ok"]
    assert re.search(r"<stdin>: line 2: record longer than 1 MiB", err), err
    assert "1 of 2 rows had errors" in err


def test_bad_quote_resumes_after_the_record():
    """Text after a closing quote: the record is skipped to its end, past a
    quoted field with a line break."""
    rec = f'"x"y,"a\nb",0,0,0,7000,0\n'
    code, out, err = run_csv(HEAD + rec + GOOD)
    assert code == 1
    assert [r["status"] for r in parse(out)] == ["ERR_PARSE", "OK"]
    assert "line 2" in err and "quote" in err


@pytest.mark.parametrize("text", ["0x1B58", "0X1b58", "-0x1B58", "+0x1B58", "0x1p3", "0x1.8p1",
                                  "0x", "1e3x"])
def test_hexadecimal_numbers_are_parse_errors(text):
    """Decimal only: strtod's hexadecimal forms are no number (0x1B58 was read
    as 7000, a plausible radius)."""
    code, out, err = run_csv(HEAD + f"h,{AU},0,0,0,{text},0\n" + GOOD)
    assert code == 1
    assert [r["status"] for r in parse(out)] == ["ERR_PARSE", "OK"]
    assert f'line 2, column 6: expected a number for target_y, got "{text}"' in err


@pytest.mark.parametrize("text", ["inf", "-Infinity", "nan", "NAN"])
def test_inf_and_nan_words_are_numbers(text):
    """docs/planner.md: nan and inf are read as numbers, the library refuses them."""
    code, out, err = run_csv(HEAD + f"w,{AU},0,0,0,{text},0\n")
    assert code == 1
    assert [r["status"] for r in parse(out)] == ["ERR_NONFINITE"]


def test_second_bom_in_the_header_is_refused():
    """A header saved with two byte-order marks: the id column was an unknown
    column and the ids row numbers; now the header is refused, naming the line."""
    code, out, err = run_csv(b"\xef\xbb\xbf\xef\xbb\xbf" + (HEAD + GOOD).encode())
    assert code == 2 and out == ""
    assert "line 1: cannot read the header: a UTF-8 byte-order mark" in err
    assert "unknown column" not in err


def test_bom_of_a_second_file_joined_is_an_error():
    """Two files joined: the second file's mark (and header) is a failed row
    naming its line; the rows around it keep their ids."""
    one = b"\xef\xbb\xbf" + (HEAD + GOOD).encode()
    code, out, err = run_csv(one + one)
    assert code == 1
    rows = parse(out)
    assert [r["status"] for r in rows] == ["OK", "ERR_PARSE", "OK"]
    assert [r["id"] for r in rows] == ["ok", "", "ok"]
    assert "line 3: a UTF-8 byte-order mark" in err


def test_first_bom_and_other_ef_text_still_read():
    """The mark at the start is skipped; other text with the byte 0xEF (U+FF0C,
    U+FEFE) is text."""
    code, out, err = run_csv(b"\xef\xbb\xbf" + HEAD.encode() +
                             f"\uff0c\ufefe,{AU},0,0,0,7000,0\n".encode())
    assert code == 0, err
    assert [r["id"] for r in parse(out)] == ["\uff0c\ufefe"]


# ------------------------------------------------------------ the sky words

def _help_sky_words():
    code, out, _ = run(["--help"])
    assert code == 0
    m = re.search(r"sky \(the camera's background behind the target, not e_sky:\s*(.*?)"
                  r" joined by '\+',\s*or all = ([a-z+]+);", out, re.S)
    assert m, out
    return out, [w.strip() for w in m.group(1).split(",")], m.group(2).split("+")


def _docs_sky_words():
    doc = (ROOT / "docs" / "planner.md").read_text()
    row = next(line for line in doc.splitlines() if line.startswith("| `sky` |"))
    listed = row.split("):", 1)[1].split("; default")[0]
    return doc, set(re.findall(r"`(\w+)`", listed))


def _header_sky_flags():
    h = (ROOT / "include" / "orbillum.h").read_text()
    return {m.lower() for m in re.findall(r"#define OI_SKY_(\w+)\s+\(\d+u\)", h)}


def test_help_lists_every_sky_word_the_planner_accepts():
    """The sky words of --help are the planner's (each accepted, `all` as
    listed), the docs' and every OI_SKY_* flag's of the library header (today
    `starlight` was missing from --help); a word in none of them is refused."""
    _, words, all_is = _help_sky_words()
    assert "starlight" in words
    assert _header_sky_flags() <= set(words), (words, _header_sky_flags())
    _, doc_words = _docs_sky_words()
    assert doc_words == set(words) | {"all"}, doc_words
    up = dict(LIT, observer_x=0, observer_y=6990, observer_z=0, camera="telescope-15cm",
              moon_x=0, moon_y=-384400, moon_z=0)
    rows = ([dict(up, id=w, sky=w) for w in words] + [dict(up, id="all", sky="all"),
            dict(up, id="all_is", sky="+".join(all_is)), dict(up, id="stars", sky="stars")])
    code, out, err = run_csv(table(rows))
    got = {r["id"]: r for r in parse(out)}
    for w in words + ["all"]:
        assert got[w]["status"] == "OK", (w, err)
    assert dict(got["all_is"], id="all") == got["all"]
    assert got["stars"]["status"] == "ERR_PARSE"


def test_help_and_docs_tell_e_sky_from_the_sky_column():
    """One sentence each: e_sky is scattered sunlight on the target (terms
    ...+sky); the sky column is the camera's background."""
    out, _, _ = _help_sky_words()
    flat = " ".join(out.split())
    assert re.search(r"e_sky: the sunlight the atmosphere scatters onto the target "
                     r"\(W/m\^2, terms=\.\.\.\+sky\)[^.]*not the sky column", flat), flat
    assert "sky (the camera's background behind the target, not e_sky" in flat
    doc, _ = _docs_sky_words()
    flat = " ".join(doc.split())
    assert re.search(r"`e_sky` \(after `detect_margin_mag`\): the sunlight the atmosphere "
                     r"scatters onto the target.{0,200}?not the `sky` column", flat)
    assert re.search(r"\| `sky` \| no \| the camera's background behind the target[^|]*"
                     r"not `e_sky`", flat)
