/**
 * The independent diagnosis benchmark: world-simulator campaigns read as measurement files and
 * diagnosed blind, scored against each scenario's expected answer (docs/diagnosis-benchmark.md).
 */
package org.robopro.app.benchmark;
