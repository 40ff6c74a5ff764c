package launch;

import java.io.File;
import java.lang.module.ModuleFinder;
import java.net.URISyntaxException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The {@code java} command that runs this program again in a JVM of its own: the same JDK, the same class path
 * (the project's, also under {@code mvn exec:java}, which loads it in a class loader of its own) and the Vector API
 * module when this JVM has it. For the render daemon and for benchmarks that time a fresh JVM.
 *
 * @param java the {@code java} executable of this JVM's JDK
 * @param options the JVM options: {@code --add-modules jdk.incubator.vector} when this JVM has the module
 * @param classPath this program's class path
 */
public record JavaLaunch(String java, List<String> options, String classPath) {
    private static final String VECTOR_MODULE = "jdk.incubator.vector";

    /**
     * How to run this program again.
     *
     * @return the launch of this JVM's JDK, module options and class path
     */
    public static JavaLaunch ofThisProgram() {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> options = ModuleLayer.boot().findModule(VECTOR_MODULE).isPresent()
                ? List.of("--add-modules", VECTOR_MODULE)
                : List.of();
        return new JavaLaunch(java, options, programClassPath());
    }

    /**
     * This launch with the Vector API module whenever the JDK has it, whether or not this JVM was given it.
     *
     * @return the launch with {@code --add-modules jdk.incubator.vector}, or this one if the JDK lacks the module
     */
    public JavaLaunch withVectorApi() {
        if (options.contains(VECTOR_MODULE)
                || ModuleFinder.ofSystem().find(VECTOR_MODULE).isEmpty()) return this;
        List<String> withModule = new ArrayList<>(options);
        withModule.addAll(List.of("--add-modules", VECTOR_MODULE));
        return new JavaLaunch(java, List.copyOf(withModule), classPath);
    }

    /**
     * The command that runs {@code mainClass} with {@code args}.
     *
     * @param mainClass the class whose {@code main} runs
     * @param args its arguments
     * @return {@code java OPTIONS -cp CLASSPATH mainClass ARGS}
     */
    public List<String> command(String mainClass, List<String> args) {
        List<String> command = new ArrayList<>();
        command.add(java);
        command.addAll(options);
        command.add("-cp");
        command.add(classPath);
        command.add(mainClass);
        command.addAll(args);
        return command;
    }

    private static String programClassPath() {
        if (Thread.currentThread().getContextClassLoader() instanceof URLClassLoader loader) {
            StringBuilder path = new StringBuilder();
            for (URL url : loader.getURLs()) {
                try {
                    if (path.length() > 0) path.append(File.pathSeparator);
                    path.append(Path.of(url.toURI()));
                } catch (URISyntaxException e) {
                    throw new IllegalStateException("class path entry " + url + " is not a file", e);
                }
            }
            if (path.length() > 0) return path.toString();
        }
        return System.getProperty("java.class.path");
    }
}
