"""The Examples sections of the main public entry points run and print what they show."""

import doctest
import importlib

import pytest

ENTRY_POINTS = [
    "optbound.sets.ellipsoid:Ellipsoid",
    "optbound.sets.zonotope:Zonotope",
    "optbound.sets.constrained_zonotope:ConstrainedZonotope",
    "optbound.sets.quadratic:QuadraticSet",
    "optbound.sets.strip:Strip",
    "optbound.sets.lifting:PolynomialLifting",
    "optbound.sets.pseudo_ellipsoid:PseudoEllipsoid",
    "optbound.analytic.strip_fusion:intersect_strip",
    "optbound.analytic.minkowski:minkowski_sum",
    "optbound.analytic.bounding_update:bounding_update",
    "optbound.analytic.affine:affine_map",
    "optbound.analytic.arc_noise:parabola_arc_ellipse",
    "optbound.optimal.intersection:outer_ellipsoid",
    "optbound.optimal.minkowski:minkowski_outer",
    "optbound.optimal.enclosing:mvee",
    "optbound.optimal.khachiyan:khachiyan_mvee",
    "optbound.interval.sivia:sivia",
    "optbound.interval.interval:Interval",
    "optbound.interval.relaxed:relaxed_paving",
    "optbound.interval.relaxed:min_outliers",
    "optbound.compare.metrics:volume_ratio",
    "optbound.compare.containment:contains",
    "optbound.compare.size:size_bracket",
    "optbound.compare.exact:contains_set",
    "optbound.compare.tri:tri_contains",
    "optbound.localization.sonar:localize",
    "optbound.localization.visibility:track",
    "optbound.localization.relative_bearing:localize",
    "optbound.localization.linearized_bearing:linearized_localize",
    "optbound.localization.landmarks:linear_position_bound",
    "optbound.localization.landmarks:pose_paving",
    "optbound.localization.tracker:SetTracker",
    "optbound.compare.proof:prove_contains",
    "optbound.estimation.system:LinearSystem",
    "optbound.estimation.exact:exact_sets",
    "optbound.estimation.observers:observe",
    "optbound.estimation.exact_polytope:exact_polytopes",
    "optbound.estimation.references:proven_contains",
    "optbound.problems.audit:evaluate",
    "optbound.problems:families",
    "optbound.problems:suite",
    "optbound.problems.problem:Problem",
    "optbound.problems.registry:load",
    "optbound.scenarios.alamo2005:system",
    "optbound.scenarios.arena:simulate",
    "optbound.scenarios.bh_geometry:sect5_instance",
    "optbound.scenarios.linear_systems:random_system",
    "optbound.scenarios.office:office_map",
    "optbound.scenarios.office:simulate",
    "optbound.report.document:write_report",
    "optbound.report.drawing:Drawings",
    "optbound.report.results:save_results",
    "optbound.report.readme:headline_refusal",
    "optbound.report.summary:ratio_stats",
    "optbound.report.tables:markdown_table",
    "optbound.bench.family:Family",
    "optbound.bench.run_folder:RunFolder",
    "optbound.bench.records:ratio",
    "optbound.bench.timing:speed_record",
    "optbound.bench.user_estimators:problem_families",
    "optbound.bench.executors:check_available",
]


@pytest.mark.parametrize("name", ENTRY_POINTS)
def test_docstring_examples_run(name):
    module, attr = name.split(":")
    mod = importlib.import_module(module)
    tests = doctest.DocTestFinder(recurse=False).find(getattr(mod, attr), name, module=mod)
    (test,) = tests
    assert test.examples, f"{name} has no Examples"
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    runner.run(test)
    assert runner.summarize(verbose=False).failed == 0
