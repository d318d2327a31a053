"""The end of every packaging test script: each failure on its own line, then the summary line
ctest shows, and the exit status (1 when anything failed)."""


def report(failures):
    for f in failures:
        print("FAIL", f)
    print(f"{0 if failures else 1} passed, {1 if failures else 0} failed")
    return 1 if failures else 0
