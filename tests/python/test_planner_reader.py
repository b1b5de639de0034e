# SPDX-License-Identifier: MIT
"""The planner's reader on hostile input (issue 28): a record near the 1 MiB
limit read in linear time, a record too long skipped to its own end (never
resumed inside its quotes) and reported at the line where it began, numbers
in decimal only, a byte-order mark only at the start of the file."""
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
