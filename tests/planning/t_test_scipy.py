#!/usr/bin/env python3
"""Recomputes with scipy the expected values statistics_test.cpp commits (PairedTTest.AgreesWithScipy,
StudentT.IncompleteBetaAndCdfAgreeWithScipy), so that they stay scipy's and not copies of our own
output. Exit 77 (ctest: skipped) when scipy is not installed."""
import sys

try:
    from scipy import special, stats
except ImportError:
    print("scipy is not installed (python3-scipy): skipped")
    sys.exit(77)

T_TESTS = [  # (a, b, t, p, df) as in statistics_test.cpp
    ([12.1, 14.3, 11.8, 15.2, 13.9, 12.7, 14.8, 13.1], [11.4, 13.9, 12.0, 14.1, 13.2, 12.9, 13.6, 12.2],
     3.016335541394574, 0.019486909530508953, 7),
    ([3.0, 2.5, 4.1, 3.3, 2.9], [3.3, 2.4, 4.4, 3.5, 3.0], -2.138089935299395, 0.09930068321372677, 4),
    ([61.2, 58.9, 70.1, 64.3, 59.8, 66.0, 71.2, 62.5, 60.4, 68.8, 63.1, 65.7],
     [55.0, 57.1, 61.9, 60.2, 58.8, 59.4, 64.0, 60.1, 57.7, 62.3, 61.0, 59.9], 6.384089563326369,
     5.1935994345353055e-05, 11),
    ([1.0, 2.0], [0.5, 2.5], 0.0, 1.0, 1),
]
BETAINC = [((2.5, 0.5, 0.3), 0.01892712407194565), ((0.5, 7.0, 0.9), 0.9999999780702158),
           ((30.0, 0.5, 0.999), 0.807237306159537), ((1.0, 1.0, 0.25), 0.25)]
T_CDF = [((-2.1, 4), 0.05182664315880109), ((0.7, 11), 0.7507677671528018), ((3.5, 1), 0.9114144672170953),
         ((-40.0, 9), 9.491499224669917e-12), ((0.0, 3), 0.5)]


def close(got, want):
    return abs(got - want) <= 1e-13 * max(abs(want), 1e-300) or got == want


failures = []
for a, b, t, p, df in T_TESTS:
    r = stats.ttest_rel(a, b)
    if not (close(r.statistic, t) and close(r.pvalue, p)) or len(a) - 1 != df:
        failures.append(f"ttest_rel({a}, {b}) = {r}, the test says t={t}, p={p}, df={df}")
for args, want in BETAINC:
    if not close(special.betainc(*args), want):
        failures.append(f"betainc{args} = {special.betainc(*args)!r}, the test says {want!r}")
for args, want in T_CDF:
    if not close(stats.t.cdf(*args), want):
        failures.append(f"t.cdf{args} = {stats.t.cdf(*args)!r}, the test says {want!r}")
print("\n".join(failures) or f"all {len(T_TESTS) + len(BETAINC) + len(T_CDF)} values agree with scipy {__import__('scipy').__version__}")
sys.exit(1 if failures else 0)
