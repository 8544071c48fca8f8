"""The verdict of a check run on several models, plain or as its own control (a run where the
fault it guards is put in on purpose, so the check must fail on every model)."""
import sys


def verdict(control, failed, models, fault, problem):
    """control: passes only if the check failed on all `models` (it sees `fault`); else fails
    when any model failed, naming `problem` and the models."""
    if control:
        if len(failed) != models:
            sys.exit("FAIL: with %s the check should fail on all %d, failed on %s"
                     % (fault, models, failed))
        print("control: the check fails with %s, as it must" % fault)
    elif failed:
        sys.exit("FAIL: %s: %s" % (problem, failed))
