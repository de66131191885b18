/**
 * The world: an independent physical-robot and measurement-campaign simulator, the truth that
 * tests calibration and diagnosis (docs/diagnosis-benchmark.md). It reads only the robot files
 * (models) and shares no code with kinematics or calibration: its own product-of-exponentials
 * kinematics ({@link org.robopro.world.Arm}), its own drive errors, thermal growth, gravity
 * elasticity and outside-the-catalogue errors ({@link org.robopro.world.WorldRobot},
 * {@link org.robopro.world.JointError}), campaigns written in the public measurement format
 * ({@link org.robopro.world.Campaign}) and a catalogue of scenarios with the answer a diagnosis
 * must give ({@link org.robopro.world.Scenario}, {@link org.robopro.world.Expected}).
 */
package org.robopro.world;
