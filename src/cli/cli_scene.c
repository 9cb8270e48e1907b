/* cli_scene — file naming and deck loading for the CLI (see cli_scene.h). */
#include "cli/cli_scene.h"
#include "cli/cli.h"
#include "util/mem.h"
#include "vm_cms_shim/cms_cp.h"
#include "vm_cms_shim/cms_deck.h"
#include "vm_cms_shim/cms_name.h"
#include <string.h>

const char cli_files_help[] =
    "  --disk L=DIR          CMS disk L is host directory DIR (repeatable; else\n"
    "                        MAPRT_DISK_L, and A is the current directory)\n"
    "  --read-as FORM        read the deck as text, punch, ebcdic, vstream or rdw\n"
    "                        (default: detected from its content)\n"
    "  --cp CP               EBCDIC code page of the deck, 037 or 1047 (default:\n"
    "                        detected where the bytes decide it, else 1047)\n";

int cli_files_init(cli_files *f, diag *err)
{
    memset(f, 0, sizeof *f);
    cms_disks_init(&f->disks);
    f->decode.form = CMS_FORM_AUTO;
    f->decode.cp = CMS_CP_AUTO;
    return cms_disks_from_env(&f->disks, err);
}

void cli_files_free(cli_files *f) { cms_disks_free(&f->disks); }

int cli_files_option(cli_files *f, const char *cmd, int argc, char **argv, int *i, int *status)
{
    const char *a = argv[*i], *v;
    diag err;
    if (strcmp(a, "--disk") && strcmp(a, "--read-as") && strcmp(a, "--cp"))
        return 0;
    *status = CLI_USAGE;
    if (!(v = cli_value(cmd, argc, argv, i)))
        return 1;
    diag_init(&err);
    if (!strcmp(a, "--disk")) {
        if (cms_disks_set(&f->disks, v, &err)) {
            cli_usage_error(cmd, "--disk: %s", err.msg);
            return 1;
        }
    } else if (!strcmp(a, "--read-as")) {
        if (!cms_form_parse(v, &f->decode.form)) {
            cli_usage_error(cmd, "--read-as: '%s' is not text, punch, ebcdic, vstream or rdw", v);
            return 1;
        }
    } else if (!cms_cp_parse(v, &f->decode.cp)) {
        cli_usage_error(cmd, "--cp: '%s' is not a code page (037 or 1047)", v);
        return 1;
    }
    *status = 0;
    return 1;
}

int cli_scene_load(const cli_files *f, const char *name, scene **out, diag *err)
{
    cms_deck *deck;
    recsrc src;
    int st = cms_deck_open(&deck, &src, &f->disks, name, &f->decode, err);
    if (st)
        return st;
    st = scene_parse(&src, out, err);
    cms_deck_close(deck);
    return st;
}

int cli_output_path(const cli_files *f, const char *name, char **path, diag *err)
{
    cms_name n;
    int st = cms_name_output(&f->disks, name, &n, err);
    if (st)
        return st;
    *path = n.path;
    n.path = NULL;
    cms_name_free(&n);
    return 0;
}
