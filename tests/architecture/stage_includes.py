"""Each stage under src/ includes only stages listed before it in src/CMakeLists.txt.

The stage order is read from src/CMakeLists.txt's add_subdirectory() lines, so a stage added there
is checked with no change here. A file in src/<stage>/ may include "<earlier stage>/...", its own
stage's headers and the public talkface/ headers; src/cli/ (the command, a shell around the
library) may include any stage. A folder of sources under src/ that is neither listed nor cli/ is
an error too: its place in the pipeline would be unknown.

Run as a program (ctest does): stage_includes.py SRC_DIR; exits 1 listing every violation.
"""
import pathlib
import re
import sys

SHELLS = ("cli",)
SOURCE_SUFFIXES = (".cpp", ".hpp", ".h", ".c", ".inc")
ADD_SUBDIRECTORY = re.compile(r"^\s*add_subdirectory\(\s*([A-Za-z0-9_]+)\s*\)", re.MULTILINE)
INCLUDE = re.compile(r'^\s*#\s*include\s*["<]([^">]+)[">]', re.MULTILINE)


def stage_order(src_dir):
    """The stages in pipeline order, as src/CMakeLists.txt adds them (comments skipped)."""
    text = (src_dir / "CMakeLists.txt").read_text(encoding="utf-8")
    text = re.sub(r"#[^\n]*", "", text)
    return ADD_SUBDIRECTORY.findall(text)


def violations(src_dir):
    src_dir = pathlib.Path(src_dir)
    order = stage_order(src_dir)
    rank = {stage: index for index, stage in enumerate(order)}
    folders = sorted(p.name for p in src_dir.iterdir() if p.is_dir())
    found = []
    for folder in folders:
        sources = [p for p in sorted((src_dir / folder).rglob("*")) if p.suffix in SOURCE_SUFFIXES]
        if not sources:
            continue
        if folder not in rank and folder not in SHELLS:
            found.append(f"src/{folder}/: not a stage of src/CMakeLists.txt (add_subdirectory({folder}) "
                         f"in pipeline order) and not a shell ({', '.join(SHELLS)})")
            continue
        for path in sources:
            text = path.read_text(encoding="utf-8", errors="replace")
            for match in INCLUDE.finditer(text):
                included = match.group(1)
                head = included.split("/", 1)[0]
                if "/" not in included or head not in rank or folder in SHELLS:
                    continue
                if rank[head] > rank[folder]:
                    line = text.count("\n", 0, match.start()) + 1
                    found.append(f"{path.relative_to(src_dir.parent)}:{line}: {folder}/ includes "
                                 f"\"{included}\", but {head}/ comes after {folder}/ in src/CMakeLists.txt "
                                 f"(a stage includes only the stages listed before it)")
    return order, found


def main(argv):
    if len(argv) != 2:
        print("usage: stage_includes.py SRC_DIR", file=sys.stderr)
        return 2
    order, found = violations(argv[1])
    if not order:
        print(f"{argv[1]}/CMakeLists.txt: no add_subdirectory() stages found", file=sys.stderr)
        return 1
    for message in found:
        print(message, file=sys.stderr)
    if found:
        return 1
    print("stages in order: " + " ".join(order))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
