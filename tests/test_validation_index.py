"""The validation index (validation/README.md) against the results it
summarises: its table is what validation/make_index.py writes from
validation/results/*.csv, a changed number in it is found, the links of the
index and the case pages (validation/cases/) resolve, and no page names an
issue number."""

import pathlib
import re
import subprocess
import sys

from foamcase import ROOT

VALIDATION = ROOT / "validation"
SCRIPT = VALIDATION / "make_index.py"
README = VALIDATION / "README.md"
BEGIN = "<!-- index: begin"
END = "<!-- index: end -->"


def check(readme):
    return subprocess.run([sys.executable, str(SCRIPT), "--check", "--readme", str(readme)],
                          capture_output=True, text=True)


def test_the_index_matches_the_results():
    """validation/README.md's table is the one make_index.py writes from
    results/*.csv; when a results file changes, rerun the script."""
    result = check(README)
    assert result.returncode == 0, result.stdout + result.stderr


def test_the_check_finds_a_changed_number(tmp_path):
    """A copy of the index with one figure of the table changed (the first
    percentage) fails the check, and the check names the line."""
    text = README.read_text()
    start, stop = text.index(BEGIN), text.index(END)
    table = text[start:stop]
    match = re.search(r"[-+]?\d+\.\d+ %", table)
    assert match, "no percentage in the index's table"
    changed = table[:match.start()] + "+99.99 %" + table[match.end():]
    broken = tmp_path / "README.md"
    broken.write_text(text[:start] + changed + text[stop:])
    result = check(broken)
    assert result.returncode == 1, result.stdout + result.stderr
    assert "+99.99 %" in result.stdout


def pages():
    return [README] + sorted((VALIDATION / "cases").glob("*.md"))


def slug(heading):
    """GitHub's anchor of a Markdown heading."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def anchors(path):
    return {slug(line.lstrip("#")) for line in path.read_text().splitlines()
            if line.startswith("#")}


def in_progress(readme_text):
    """Pages of index rows whose result is 'in progress': written by others,
    possibly not yet there."""
    found = set()
    for line in readme_text.splitlines():
        if line.startswith("|") and "| in progress |" in line:
            found.update(re.findall(r"\]\((cases/[^)#\s]+)", line))
    return found


def test_the_links_resolve():
    """Every relative link of the index and the case pages names a file
    that exists and, with an anchor, a heading of that page; an index row
    still in progress may link to a page not yet written."""
    pending = in_progress(README.read_text())
    broken = []
    for page in pages():
        text = re.sub(r"```.*?```", "", page.read_text(), flags=re.S)
        for target, anchor in re.findall(r"\]\(([^)#\s]*)(?:#([^)\s]+))?\)", text):
            if re.match(r"\w+://", target):
                continue
            path = (page.parent / target).resolve() if target else page
            if not path.exists():
                if page == README and target in pending:
                    continue
                broken.append(f"{page.relative_to(ROOT)}: {target}")
            elif anchor and path.suffix == ".md" and anchor not in anchors(path):
                broken.append(f"{page.relative_to(ROOT)}: {target}#{anchor}")
    assert not broken, "broken links: " + ", ".join(broken)


def test_every_case_page_is_in_the_index():
    index = README.read_text()
    missing = [p.name for p in sorted((VALIDATION / "cases").glob("*.md"))
               if f"(cases/{p.name}" not in index]
    assert not missing, "case pages not linked from validation/README.md: " + ", ".join(missing)


def test_no_page_names_an_issue_number():
    found = []
    for page in pages():
        for number, line in enumerate(page.read_text().splitlines(), 1):
            if re.search(r"\bissues?\s*#?\s*\d+|(?<![\w&])#\d+\b", line, re.I):
                found.append(f"{page.relative_to(ROOT)}:{number}: {line.strip()}")
    assert not found, "\n".join(found)
