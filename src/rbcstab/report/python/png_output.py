"""Writing a figure so that a reader never sees half a PNG (shared by the bench plotting scripts)."""
import os


def save_png(fig, out, dpi):
    """Draws fig to a hidden sibling of out, then renames it onto out."""
    tmp = os.path.join(os.path.dirname(out) or ".", ".%s.tmp-%d-py" % (os.path.basename(out), os.getpid()))
    try:
        fig.savefig(tmp, dpi=dpi, format="png")
        os.replace(tmp, out)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)
