"""Tamias2D traceability harness.

Joins the SRS data (srs/*.yaml), code tags (\\srs{LABEL} comments), test results (CTest,
Boost.Test JUnit + --list_content=DOT) and verification results (reports/data/*.json) into an
auditor's report (reports/index.html, traceability.md, traceability.json) and its ReqIF export
(reports/tamias2d.reqif).

Entry point: traceability/build_report.py. Documentation: docs/traceability.md.
"""

SCHEMA_VERSION = "1.6"
