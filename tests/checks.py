"""The tally the command-line tests keep: every check counted, each failure printed as it
happens and listed at the end. Imported by the cli_*_test.py scripts beside it."""

passed, failed = 0, []


def check(name, cond, detail=""):
    """Counts `cond`; a failure prints its name and detail at once."""
    global passed
    if cond:
        passed += 1
    else:
        failed.append("%s %s" % (name, detail))
        print("FAIL", name, detail)
    return bool(cond)


def summary():
    """Prints the tally and returns the script's exit status (1 when anything failed)."""
    print("%d passed, %d failed" % (passed, len(failed)))
    for f in failed:
        print("  failed:", f)
    return 1 if failed else 0
