/**
 * The command line (picocli): one small class per subcommand, each parsing its options, calling
 * the library and printing through the command line's writers, and returning an exit code
 * ({@link org.robopro.app.cli.Failures} turns every failure into one line and its code).
 */
package org.robopro.app.cli;
