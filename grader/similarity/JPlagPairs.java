// The grader's bridge to JPlag 4.3.0 (de.jplag:jplag, a library on Maven Central: the project has no
// command-line artifact there). One run compares every pair of submission folders under ROOT in one
// language, with the folder BASE as JPlag's base code (the template: what the course hands out), and
// writes what similarity.py needs as tab-separated lines, each field free of tabs and line breaks
// (the folders and files are the grader's own staged names, never a student's):
//   V <JPlag's version> <the language module's name> <its minimum match, in tokens>
//   S <submission> <tokens> <tokens matched by the template> <parsed: 1|0>
//   F <file> <tokens>                                the files of the S line above, with their tokens
//   P <a> <b> <similarity> <matched tokens>         one per pair with at least one match
//   M <a file> <a first line> <a last line> <b file> <b first line> <b last line> <tokens>
//                                                    the matches of the P line above
// usage: java -cp LIB/* JPlagPairs.java cpp ROOT BASE SUFFIXES MIN_TOKENS OUT   (SUFFIXES: .cpp,.hpp;
//        BASE - for none)
// Exit 0 with the file written; 1 naming the fault (JPlag's own message) otherwise.
import de.jplag.JPlag;
import de.jplag.JPlagComparison;
import de.jplag.JPlagResult;
import de.jplag.Match;
import de.jplag.SharedTokenType;
import de.jplag.Submission;
import de.jplag.Token;
import de.jplag.clustering.ClusteringOptions;
import de.jplag.options.JPlagOptions;

import java.io.BufferedWriter;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

public final class JPlagPairs {
    private JPlagPairs() {}

    // The file of a token, relative to its submission's folder, with forward slashes.
    static String relative(Submission submission, Token token) {
        return submission.getRoot().toPath().relativize(token.getFile().toPath()).toString().replace('\\', '/');
    }

    // One side of a match: its file and the first and last line its tokens cover there.
    static String side(Submission submission, int start, int length) {
        List<Token> tokens = submission.getTokenList();
        Token first = tokens.get(start);
        int low = first.getLine(), high = first.getLine();
        for (int i = start; i < start + length && i < tokens.size(); ++i) {
            Token t = tokens.get(i);
            if (!t.getFile().equals(first.getFile()) || t.getLine() <= 0) continue;
            low = Math.min(low, t.getLine());
            high = Math.max(high, t.getLine());
        }
        return relative(submission, first) + "\t" + low + "\t" + high;
    }

    public static void main(String[] args) throws IOException {
        if (args.length != 6) {
            System.err.println("usage: JPlagPairs cpp ROOT BASE SUFFIXES MIN_TOKENS OUT");
            System.exit(2);
        }
        Path out = Path.of(args[5]);
        Path partial = Path.of(args[5] + ".partial");
        try {
            JPlagOptions options = new JPlagOptions(new de.jplag.cpp.Language(), Set.of(new File(args[1])), Set.of())
                    .withFileSuffixes(Arrays.asList(args[3].split(",")))
                    .withMinimumTokenMatch(Integer.parseInt(args[4]))
                    .withSimilarityThreshold(0.0)
                    .withMaximumNumberOfComparisons(JPlagOptions.SHOW_ALL_COMPARISONS)
                    .withClusteringOptions(new ClusteringOptions().withEnabled(false));
            if (!args[2].equals("-")) options = options.withBaseCodeSubmissionDirectory(new File(args[2]));
            JPlagResult result = new JPlag(options).run();
            try (BufferedWriter w = Files.newBufferedWriter(partial, StandardCharsets.UTF_8)) {
                w.write("V\t" + JPlag.JPLAG_VERSION + "\t" + options.language().getName() + "\t"
                        + options.minimumTokenMatch() + "\n");
                for (Submission s : result.getSubmissions().getSubmissions()) {
                    int template = s.hasBaseCodeMatches() ? s.getBaseCodeComparison().getNumberOfMatchedTokens() : 0;
                    w.write("S\t" + s.getName() + "\t" + s.getNumberOfTokens() + "\t" + template + "\t1\n");
                    Map<String, Integer> perFile = new TreeMap<>();
                    for (Token t : s.getTokenList())
                        if (t.getType() != SharedTokenType.FILE_END) perFile.merge(relative(s, t), 1, Integer::sum);
                    for (Map.Entry<String, Integer> file : perFile.entrySet())
                        w.write("F\t" + file.getKey() + "\t" + file.getValue() + "\n");
                }
                for (Submission s : result.getSubmissions().getInvalidSubmissions())
                    w.write("S\t" + s.getName() + "\t0\t0\t0\n");
                for (JPlagComparison c : result.getAllComparisons()) {
                    if (c.getNumberOfMatchedTokens() == 0) continue;
                    Submission a = c.firstSubmission(), b = c.secondSubmission();
                    w.write("P\t" + a.getName() + "\t" + b.getName() + "\t" + c.similarity() + "\t"
                            + c.getNumberOfMatchedTokens() + "\n");
                    for (Match m : c.matches())
                        w.write("M\t" + side(a, m.startOfFirst(), m.length()) + "\t" + side(b, m.startOfSecond(), m.length())
                                + "\t" + m.length() + "\n");
                }
            }
            Files.move(partial, out, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } catch (Exception | LinkageError error) {
            Files.deleteIfExists(partial);
            System.err.println("JPlag " + args[0] + ": " + error.getMessage());
            System.exit(1);
        }
    }
}
