package distributed;

import cli.BadInputException;
import cli.OutputFile;
import java.nio.file.Path;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The file names of an animation's frames: a PNG path with one frame-number conversion, {@code %d} or a
 * zero-padded {@code %04d}, e.g. {@code frames/orbit-%04d.png} gives {@code frames/orbit-0000.png}, ...
 */
record FramePattern(String pattern) {
    private static final Pattern NUMBER = Pattern.compile("%(0[1-9])?d");

    /** Checks the pattern, and that the first and last frame can be written (see {@link OutputFile}). */
    static FramePattern check(String pattern, int frames, boolean createFolder) throws BadInputException {
        Matcher m = NUMBER.matcher(pattern);
        int conversions = 0;
        while (m.find()) conversions++;
        if (conversions != 1 || NUMBER.matcher(pattern).replaceAll("").contains("%")) {
            throw new BadInputException("output " + pattern + ": must hold one frame number, %d or %04d, and no"
                    + " other %, e.g. images/orbit-%04d.png");
        }
        FramePattern p = new FramePattern(pattern);
        OutputFile.check(p.file(0), createFolder);
        OutputFile.check(p.file(frames - 1), false);
        return p;
    }

    /** The file of {@code frame}. */
    Path file(int frame) {
        return Path.of(String.format(Locale.ROOT, pattern, frame));
    }
}
