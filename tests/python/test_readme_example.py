"""The README's Python example (its ```python block) run as a user pastes it, in a folder holding the
files it names: speech.wav and speech.txt (the test clip one_sentence), so the front page's example keeps
working as the API changes."""
import pathlib
import re
import shutil

ROOT = pathlib.Path(__file__).parents[2]
CLIPS_DIR = ROOT / "tests" / "data" / "speech"


def test_the_readme_python_example_runs(tmp_path, monkeypatch, capsys):
    example = re.search(r"```python\n(.*?)```", (ROOT / "README.md").read_text(encoding="utf-8"), re.S)
    assert example, "README.md has no ```python example"
    shutil.copy(CLIPS_DIR / "one_sentence.wav", tmp_path / "speech.wav")
    shutil.copy(CLIPS_DIR / "one_sentence.txt", tmp_path / "speech.txt")
    monkeypatch.chdir(tmp_path)
    namespace = {}
    exec(compile(example.group(1), "README.md", "exec"), namespace)
    assert (tmp_path / "face.svg").read_text(encoding="utf-8").lstrip().startswith("<")
    assert namespace["timeline"].syllables
    assert "(72, 2)" in capsys.readouterr().out
