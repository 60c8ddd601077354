"""What the output checks share: the grids of the XDMF index, and the list of failed checks that
a script prints and exits 1 on at its end."""
import sys

GRIDS = ["cells", "solids", "obstacles", "particles"]
failures = []


def check(ok, what):
    """Records `what` as failed when ok is false; returns ok."""
    if not ok:
        failures.append(what)
    return ok


def finish(summary):
    """Prints every failure and exits 1, or prints the summary of what passed."""
    if failures:
        print("\n".join("FAIL: " + f for f in failures))
        sys.exit(1)
    print(summary)
