/* cli_dl — shared display-list options (see cli_dl.h). */
#include "cli/cli_dl.h"
#include "cli/cli.h"
#include "display5080/dl_format.h"
#include <string.h>

int cli_dl_parse(const char *cmd, int argc, char **argv, int first, unsigned allowed, int nfiles,
                 const char *files, cli_dl_args *out)
{
    cli_dl_args a;
    int i, n = 0, size_given = 0;
    memset(&a, 0, sizeof a);
    for (i = first; i < argc; i++) {
        const char *o = argv[i], *v;
        if ((allowed & CLI_DL_DAC) && !strcmp(o, "--dac")) {
            if (!(v = cli_value(cmd, argc, argv, &i)))
                return CLI_USAGE;
            if (strcmp(v, "4") && strcmp(v, "8"))
                return cli_usage_error(cmd, "--dac: '%s' is not 4 or 8", v);
            a.dac = v[0] - '0';
        } else if ((allowed & CLI_DL_RAW) && !strcmp(o, "--raw")) {
            a.raw = 1;
        } else if ((allowed & CLI_DL_RAW) && !strcmp(o, "--size")) {
            if (!(v = cli_value(cmd, argc, argv, &i)) ||
                cli_size(cmd, "--size", v, DL_MAX_SIDE, &a.width, &a.height))
                return CLI_USAGE;
            size_given = 1;
        } else if ((allowed & CLI_DL_DITHER) && !strcmp(o, "--dither")) {
            a.dither = 1;
        } else if ((allowed & CLI_DL_STATS) && !strcmp(o, "--stats")) {
            a.stats = 1;
        } else if ((allowed & CLI_DL_TRUECOLOR) && !strcmp(o, "--truecolor")) {
            a.truecolor = 1;
        } else if ((allowed & CLI_DL_BACKEND) && !strcmp(o, "--backend")) {
            if (!(a.backend = cli_value(cmd, argc, argv, &i)))
                return CLI_USAGE;
        } else if (o[0] == '-' && o[1]) {
            return cli_usage_error(cmd, "unknown option '%s'", o);
        } else if (n < nfiles) {
            a.file[n++] = o;
        } else {
            return cli_usage_error(cmd, "unexpected argument '%s'", o);
        }
    }
    if (n < nfiles)
        return cli_usage_error(cmd, "needs %s", files);
    if (size_given && !a.raw)
        return cli_usage_error(cmd, "--size applies only to a --raw stream");
    *out = a;
    return 0;
}
