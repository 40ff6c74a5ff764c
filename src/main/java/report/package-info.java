/**
 * The accuracy report: error against converged references for each effect and its cost in time, with charts
 * (XChart). Tool.
 */
package report;
