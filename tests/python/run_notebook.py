"""Runs a notebook headless with nbclient (Debian's python3-nbclient and
python3-ipykernel), its kernel on this interpreter, with DW_NOTEBOOK_OUT set
to OUT_DIR; writes the executed notebook there and checks that every figure
the notebook names was written. Exit 0 when every cell ran.

    run_notebook.py NOTEBOOK.ipynb OUT_DIR"""
import os
import sys

import nbformat
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError


def main():
    notebook_path, out_dir = sys.argv[1], sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    for name in ("ssao-study.png", "ssao-study-buffers.png"):
        if os.path.exists(os.path.join(out_dir, name)):
            os.remove(os.path.join(out_dir, name))
    out_dir = os.path.abspath(out_dir)
    os.environ["DW_NOTEBOOK_OUT"] = out_dir
    # The kernel starts in out_dir: a relative PYTHONPATH would not find the module.
    paths = [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]
    os.environ["PYTHONPATH"] = os.pathsep.join(os.path.abspath(p) for p in paths)
    os.environ.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # ipykernel's debugger note on stderr
    nb = nbformat.read(notebook_path, as_version=4)
    # The kernel runs this very interpreter (the one with numpy and the module).
    client = NotebookClient(nb, timeout=300, kernel_name="python3",
                            resources={"metadata": {"path": out_dir}})
    try:
        client.execute()
    except CellExecutionError as e:
        print(e, file=sys.stderr)
        return 1
    finally:
        nbformat.write(nb, os.path.join(out_dir, os.path.basename(notebook_path)))
    text = "".join(o.get("text", "") for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", []))
    print(text)
    for name in ("ssao-study.png", "ssao-study-buffers.png"):
        path = os.path.join(out_dir, name)
        if not os.path.exists(path) or os.path.getsize(path) < 1000:
            print("the notebook did not write %s" % path, file=sys.stderr)
            return 1
        with open(path, "rb") as f:
            if f.read(8) != b"\x89PNG\r\n\x1a\n":
                print("%s is not a PNG" % path, file=sys.stderr)
                return 1
    if "picked ssao.samples=" not in text:
        print("the notebook printed no pick", file=sys.stderr)
        return 1
    print("notebook ran; figures in %s" % out_dir)
    return 0


if __name__ == "__main__":
    sys.exit(main())
