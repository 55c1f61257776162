"""The user guide (doc/) against the code: the keyword reference
(doc/reference) lists exactly the keywords the code accepts, each
run-time selectable type is documented, the guide's links resolve, and no
page names an issue number.

The code's keywords come from dlmKeywords, which prints the lists the code
checks dictionaries against (Foam::checkKeywords), and, for the few lists
it cannot reach, from the sources: the top level of
constant/particleProperties (dlmParticleCloud.C), the rigidProjection
fvOption (rigidProjection.C), the packedBed function object (packedBed.C),
the solvers' controlDict and PIMPLE entries and transportProperties.

A reference table is a Markdown table after a marker naming the
dictionaries it documents,

    <!-- keywords: wall/plane wall/cone -->
    | keyword | meaning | unit | default | values |
    |---|---|---|---|---|
    | `point` | ... |

its first column the keyword in backticks. A dictionary's keywords are
those of every table that names it (the keywords all walls share in one
table, each type's own in another). Tables of OpenFOAM's own keywords are
marked `<!-- keywords: (OpenFOAM) -->` and not compared."""

import pathlib
import re
import subprocess

import pytest

from foamcase import ROOT

DOC = ROOT / "doc"
REFERENCE = DOC / "reference"
SRC = ROOT / "src" / "dlmParticles"
SOLVERS = ROOT / "applications" / "solvers"

MARKER = re.compile(r"<!--\s*keywords:\s*(.*?)\s*-->")
OPENFOAM = "(OpenFOAM)"
ROW = re.compile(r"^\|\s*`([A-Za-z_][\w.]*)`\s*\|")

# The reference page of each family's types (dlmKeywords' "types" lines)
FAMILY_PAGES = {
    "shape": "particleProperties.md",
    "pair": "contact.md",
    "wall": "contact.md",
    "overlap": "contact.md",
    "outlet": "outlets.md",
    "mixedCells": "rigidProjection.md",
    "target": "dynamicMeshDict.md",
}

# Every OpenFOAM dictionary may hold its header
IGNORED = {"FoamFile"}


# * * * * * * * * * * * * * * * The reference's side * * * * * * * * * * * * //

def reference_tables(text, page="page"):
    """{dictionary: {keyword: where}} from the marked tables of a page, and
    a list of format errors (an unmarked table, a row without a keyword in
    backticks, a marker without a table). Fenced code blocks are
    examples: skipped."""
    lines = text.splitlines()
    found = {}
    errors = []
    sections = None
    marker_line = 0
    in_table = False
    fenced = False
    for number, line in enumerate(lines, 1):
        if line.startswith("```"):
            fenced = not fenced
        if fenced or line.startswith("```"):
            # An example, not a reference table
            in_table = False
            continue
        marker = MARKER.search(line)
        if marker:
            if sections is not None:
                errors.append(f"{page}:{marker_line}: marker without a table")
            sections = marker.group(1).split()
            marker_line = number
            continue
        if line.startswith("|"):
            if not in_table:
                in_table = True
                if sections is None:
                    errors.append(f"{page}:{number}: table without a "
                                  "<!-- keywords: ... --> marker")
                    current, row = None, 0
                else:
                    current, row = sections, 0
                sections = None
            row += 1
            if current is None or current == [OPENFOAM] or row <= 2:
                continue
            match = ROW.match(line)
            if not match:
                errors.append(f"{page}:{number}: row without a keyword in "
                              "backticks in its first column")
                continue
            for section in current:
                found.setdefault(section, {})[match.group(1)] = f"{page}:{number}"
        else:
            in_table = False
            if line.strip() and sections is not None:
                errors.append(f"{page}:{marker_line}: marker not followed by a table")
                sections = None
    if sections is not None:
        errors.append(f"{page}:{marker_line}: marker without a table")
    return found, errors


def reference_keywords():
    """{dictionary: {keyword: where}} over all reference pages, and the
    format errors."""
    found = {}
    errors = []
    for page in sorted(REFERENCE.glob("*.md")):
        tables, page_errors = reference_tables(page.read_text(),
                                               page.relative_to(ROOT))
        errors += page_errors
        for section, keywords in tables.items():
            found.setdefault(section, {}).update(keywords)
    return found, errors


# * * * * * * * * * * * * * * * * The code's side * * * * * * * * * * * * * * //

def dlm_keywords(env):
    """dlmKeywords' output: ({dictionary: keywords}, {family: types})."""
    result = subprocess.run(["dlmKeywords"], env=env, capture_output=True,
                            text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    keywords, types = {}, {}
    for line in result.stdout.splitlines():
        fields = line.split()
        if fields and fields[0] == "keywords":
            keywords[fields[1]] = set(fields[2:])
        elif fields and fields[0] == "types":
            types[fields[1]] = fields[2:]
    assert keywords and types, result.stdout
    return keywords, types


def literals(text):
    return set(re.findall(r'"(\w+)"', text))


def source_keywords():
    """{dictionary: keywords} read from the sources where the lists are not
    reachable from dlmKeywords. Each pattern must match: a change of the
    code that moves a list fails here, naming the file to look at."""
    found = {}

    # constant/particleProperties, top level
    path = SRC / "dlmParticleCloud" / "dlmParticleCloud.C"
    match = re.search(r"wordHashSet known\s*\(\s*\{(.*?)\}\s*\)\s*;\s*"
                      r"checkKeywords\(properties_, known\)",
                      path.read_text(), re.S)
    assert match, f"{path}: the 'known' list of checkKeywords(properties_, known) not found"
    found["particleProperties"] = literals(match.group(1))

    # The rigidProjection fvOption: fv::option's keywords, its Coeffs
    # sub-dictionary and the projection's own
    path = SRC / "fvOptions" / "rigidProjection" / "rigidProjection.C"
    text = path.read_text()
    own = re.search(r"wordHashSet own\s*\(\s*\{(.*?)\}\s*\)", text, re.S)
    known = re.search(r"wordHashSet known\s*\(\s*\{(.*?)\}\s*\)", text, re.S)
    assert own and known, f"{path}: the 'own' and 'known' lists not found"
    keywords = literals(own.group(1)) | literals(known.group(1))
    if "coeffsName" in known.group(1):
        assert 'modelType_ + "Coeffs"' in text, path
        keywords.add("rigidProjectionCoeffs")
    found["fvOption/rigidProjection"] = keywords

    # The packedBed function object's read(), with type and libs
    path = SRC / "functionObjects" / "packedBed" / "packedBed.C"
    match = re.search(r"bool Foam::functionObjects::packedBed::read\(.*?\n\}\n",
                      path.read_text(), re.S)
    assert match, f"{path}: read() not found"
    keywords = set(re.findall(
        r"dict\.(?:get|getOrDefault|getCheck|getCheckOrDefault|found|"
        r"readIfPresent|readEntry|lookup|lookupOrDefault)(?:<[^>]*>)?\(\s*\"(\w+)\"",
        match.group(0)))
    assert keywords, f"{path}: no keyword read in read()"
    found["functionObject/packedBed"] = keywords | {"type", "libs"}

    # The solvers' and the library's entries of system/controlDict,
    # system/fvSolution PIMPLE and constant/transportProperties
    sources = [p for p in list(SRC.rglob("*.[CH]")) + list(SOLVERS.rglob("*.[CH]"))
               if "lnInclude" not in p.parts and "Make" not in p.parts]
    text = "\n".join(p.read_text() for p in sources)
    read = (r"\s*\.\s*(?:get|getOrDefault|getCheck|getCheckOrDefault|found|"
            r"readIfPresent|readEntry|lookupOrDefault)(?:<[^>]*>)?\s*\(\s*\"(\w+)\"")
    found["controlDict"] = set(re.findall(r"controlDict\(\)" + read, text))
    found["fvSolution/PIMPLE"] = set(re.findall(r"pimple\.dict\(\)" + read, text))
    found["transportProperties"] = set(re.findall(
        r"dimensionedScalar\s+\w+\s*\(\s*\"(\w+)\"\s*,\s*\w+\s*,\s*transportProperties\s*\)",
        text))
    for section in ("controlDict", "fvSolution/PIMPLE", "transportProperties"):
        assert found[section], f"no {section} entry found in the sources"
    return found


@pytest.fixture(scope="module")
def code(foam_env):
    keywords, types = dlm_keywords(foam_env)
    sources = source_keywords()
    overlap = set(keywords) & set(sources)
    assert not overlap, f"listed by dlmKeywords and read from the sources: {overlap}"
    keywords.update(sources)
    return keywords, types


# * * * * * * * * * * * * * * * * * Comparison  * * * * * * * * * * * * * * * //

def differences(code_keywords, documented):
    """Lines naming each keyword the code accepts and the reference lacks,
    each the reference lists and the code does not accept, and each
    dictionary the reference documents that the code does not have."""
    problems = []
    for section in sorted(code_keywords):
        accepted = set(code_keywords[section]) - IGNORED
        listed = documented.get(section, {})
        for keyword in sorted(accepted - set(listed)):
            problems.append(f"{section}: '{keyword}' is accepted by the code but"
                            " missing from the reference")
        for keyword in sorted(set(listed) - accepted):
            problems.append(f"{section}: '{keyword}' ({listed[keyword]}) is in the"
                            " reference but not accepted by the code")
    for section in sorted(set(documented) - set(code_keywords)):
        problems.append(f"{section}: documented "
                        f"({', '.join(sorted(set(documented[section].values())))})"
                        " but no such dictionary in the code")
    return problems


def test_the_comparison_finds_what_it_should():
    """The checker itself: a table with a keyword too few and one too many,
    a table without a marker and a row without a keyword are found."""
    page = """
<!-- keywords: wall/plane wall/cone -->
| keyword | meaning |
|---|---|
| `type` | the type |

<!-- keywords: wall/plane -->
| keyword | meaning |
|---|---|
| `point` | a point |
| `bogus` | not read |

| keyword | meaning |
|---|---|
| `x` | unmarked |

<!-- keywords: wall/cone -->
| keyword | meaning |
|---|---|
| radius | no backticks |

```
| `fenced` | an example |
```
"""
    documented, errors = reference_tables(page)
    assert documented["wall/plane"].keys() == {"type", "point", "bogus"}
    assert documented["wall/cone"].keys() == {"type"}
    assert any("without a <!-- keywords" in e for e in errors), errors
    assert any("row without a keyword" in e for e in errors), errors
    problems = differences({"wall/plane": {"type", "point", "normal"},
                            "wall/cone": {"type"}}, documented)
    assert problems == [
        "wall/plane: 'normal' is accepted by the code but missing from the reference",
        "wall/plane: 'bogus' (page:11) is in the reference but not accepted by the code",
    ], problems
    assert differences({"wall/plane": {"type", "point", "bogus"}}, documented) == [
        "wall/cone: documented (page:5) but no such dictionary in the code"]


def test_the_reference_tables_are_well_formed():
    _, errors = reference_keywords()
    assert not errors, "\n".join(errors)


def test_the_reference_lists_exactly_the_keywords_the_code_accepts(code):
    code_keywords, _ = code
    documented, _ = reference_keywords()
    problems = differences(code_keywords, documented)
    assert not problems, ("doc/reference and the code differ (dlmKeywords, "
                          "tests/test_documentation.py):\n" + "\n".join(problems))


def test_every_selectable_type_is_documented(code):
    _, types = code
    assert set(types) == set(FAMILY_PAGES), set(types) ^ set(FAMILY_PAGES)
    missing = []
    for family, names in sorted(types.items()):
        text = (REFERENCE / FAMILY_PAGES[family]).read_text()
        missing += [f"{family} {name} ({FAMILY_PAGES[family]})"
                    for name in names if f"`{name}`" not in text]
    assert not missing, "types not named in the reference: " + ", ".join(missing)


# * * * * * * * * * * * * * * * * The guide's text * * * * * * * * * * * * * //

def slug(heading):
    """GitHub's anchor of a Markdown heading."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def anchors(path):
    return {slug(line.lstrip("#")) for line in path.read_text().splitlines()
            if line.startswith("#")}


def test_the_guide_links_resolve():
    broken = []
    for page in sorted(DOC.rglob("*.md")):
        text = re.sub(r"```.*?```", "", page.read_text(), flags=re.S)
        for target, anchor in re.findall(r"\]\(([^)#\s]*)(?:#([^)\s]+))?\)", text):
            if re.match(r"\w+://", target):
                continue
            path = (page.parent / target).resolve() if target else page
            if not path.exists():
                broken.append(f"{page.relative_to(ROOT)}: {target}")
            elif anchor and path.suffix == ".md" and anchor not in anchors(path):
                broken.append(f"{page.relative_to(ROOT)}: {target}#{anchor}")
    assert not broken, "broken links: " + ", ".join(broken)


def test_the_index_lists_every_page():
    index = (DOC / "README.md").read_text()
    pages = [p.relative_to(DOC).as_posix() for p in sorted(DOC.rglob("*.md"))
             if p != DOC / "README.md"]
    missing = [p for p in pages if f"]({p}" not in index]
    assert not missing, "pages not in doc/README.md: " + ", ".join(missing)


def test_the_guide_names_no_issue_number():
    found = []
    for page in sorted(DOC.rglob("*.md")):
        for number, line in enumerate(page.read_text().splitlines(), 1):
            if re.search(r"\bissues?\s*#?\s*\d+|(?<![\w&])#\d+\b", line, re.I):
                found.append(f"{page.relative_to(ROOT)}:{number}: {line.strip()}")
    assert not found, "\n".join(found)
