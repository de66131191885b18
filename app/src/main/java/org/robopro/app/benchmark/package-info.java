/**
 * The independent diagnosis benchmark: world-simulator scenarios measured, written as measurement
 * files, read back and diagnosed blind, then scored (docs/diagnosis-benchmark.md).
 */
package org.robopro.app.benchmark;
