"""Shared by hati's plot scripts (plot_suite.py, plot_records.py): a figure
saved into a folder through a temporary file created exclusively (O_EXCL)
there and renamed over its name, so that a symbolic link at the name is
refused, never followed."""
import os
import tempfile


def save(fig, folder, name, script):
    """fig into folder/name; a link there ends the script (exit code 1) with
    one line naming @script."""
    import matplotlib.pyplot as plt
    path = os.path.join(folder, name)
    if os.path.islink(path):
        raise SystemExit("%s: %s is a symbolic link: refused (a plot is never "
                         "written through a link; remove the link)" % (script, path))
    fd, temporary = tempfile.mkstemp(prefix="." + name + ".", suffix=".tmp", dir=folder)
    try:
        with os.fdopen(fd, "wb") as f:
            os.fchmod(f.fileno(), 0o644)  # mkstemp's 0600: as the other outputs
            fig.savefig(f, dpi=110, format="png")
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise
    finally:
        plt.close(fig)
