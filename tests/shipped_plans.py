"""A plan shipped in examples/ copied where a test runs it, with the
profile file its ``[arena]`` names (relative to the plan), as a user's
checkout has them side by side."""

from pathlib import Path


def copy_plan(shipped: Path, copy: Path, fallback: str) -> None:
    """``shipped`` written to ``copy`` (``fallback``'s text when no such plan
    is shipped), and its arena's profile file beside it."""
    import tomllib

    copy.parent.mkdir(parents=True, exist_ok=True)
    if not shipped.is_file():
        copy.write_text(fallback, encoding="utf-8")
        return
    text = shipped.read_text(encoding="utf-8")
    copy.write_text(text, encoding="utf-8")
    name = tomllib.loads(text).get("arena", {}).get("profile")
    if name:
        (copy.parent / name).write_bytes((shipped.parent / name).read_bytes())
