/**
 * The command line (picocli): render, report, robustness and benchmark commands, with exit codes and one-line errors
 * (docs/CLI.md). Tool: needs picocli, progressbar and Jackson.
 */
package cli;
