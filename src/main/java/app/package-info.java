/**
 * The demo scenes built in Java: the street (with its facades, cars, lamps and landmark), the showcase, the feature
 * gallery and the benchmark models. Tool.
 */
package app;
