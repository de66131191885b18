/**
 * JMH benchmarks of the speed targets in docs/performance.md: kinematics, identification,
 * compensation and diagnosis. Run with {@code java -jar bench/target/benchmarks.jar}.
 */
package org.robopro.bench;
