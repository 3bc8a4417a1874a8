"""The stage include check itself: it fails on a stage that includes a later one, on an unlisted
stage, and passes on a tree in order (so the ctest on the real src/ can fail)."""
import pathlib

import stage_includes


def make_tree(root, stages, files):
    src = root / "src"
    src.mkdir()
    (src / "CMakeLists.txt").write_text(
        "# add_subdirectory(commented_out)\n" + "".join(f"add_subdirectory({s})\n" for s in stages)
        + "if(WITH_X)\n  add_subdirectory(late)\nendif()\n")
    for name, text in files.items():
        path = src / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return src


def test_a_tree_in_order_passes(tmp_path):
    src = make_tree(tmp_path, ["common", "face", "render"], {
        "common/a.cpp": '#include "common/a.hpp"\n',
        "face/f.cpp": '#include "common/a.hpp"\n#include "talkface/face_model.hpp"\n#include "local.hpp"\n',
        "render/r.cpp": '#include "face/f.hpp"\n#include <vector>\n',
        "late/l.cpp": '#include "render/r.hpp"\n',
        "cli/main.cpp": '#include "late/l.hpp"\n',
    })
    order, found = stage_includes.violations(src)
    assert order == ["common", "face", "render", "late"]
    assert found == []


def test_a_stage_including_a_later_one_fails_naming_file_and_line(tmp_path):
    src = make_tree(tmp_path, ["common", "face", "render"], {
        "face/f.cpp": '// face\n#include "render/svg.hpp"\n',
        "face/sub/g.cpp": '#include <render/other.hpp>\n',
    })
    _, found = stage_includes.violations(src)
    assert len(found) == 2
    assert found[0].startswith("src/face/f.cpp:2: face/ includes \"render/svg.hpp\"")
    assert "src/face/sub/g.cpp:1:" in found[1]


def test_an_unlisted_stage_fails(tmp_path):
    src = make_tree(tmp_path, ["common"], {"timing/t.cpp": '#include "common/a.hpp"\n'})
    _, found = stage_includes.violations(src)
    assert len(found) == 1 and found[0].startswith("src/timing/: not a stage")


def test_the_real_tree_lists_its_stages():
    src = pathlib.Path(__file__).resolve().parents[2] / "src"
    order, _ = stage_includes.violations(src)
    assert order[0] == "common" and "render" in order and "apps" in order
