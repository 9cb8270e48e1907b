/* cmd_cms — `maprt cms import|list|type|export`: the VM/CMS shim from the
 * command line. Moves files between CMS interchange forms (Hercules tapes,
 * punch decks, EBCDIC card images, V streams) and host directories mapped to
 * CMS disks, and shows them the way LISTFILE and TYPE would. */
#include "cli/cli.h"
#include "util/sniff.h"
#include "util/diag.h"
#include "vm_cms_shim/cms_file.h"
#include "vm_cms_shim/cms_import.h"
#include <string.h>

static const char usage_text[] =
    "usage: maprt cms import FILE [--to L] [--tape|--punch] [--read-as FORM] [--cp CP] [--disk L=DIR ...]\n"
    "       maprt cms list [L|*] [--read-as FORM] [--cp CP] [--disk L=DIR ...]\n"
    "       maprt cms type NAME [--read-as FORM] [--cp CP] [--disk L=DIR ...]\n"
    "       maprt cms export NAME OUT [--form FORM] [--cp CP] [--recfm F|V] [--lrecl N]\n"
    "                        [--read-as FORM] [--read-cp CP] [--disk L=DIR ...]\n"
    "\n"
    "VM/CMS files on the host. NAME and OUT are a CMS fileid such as 'FIG1 SCENE A'\n"
    "(fn ft [fm]; fm defaults to A1, '*' searches disks A..Z) or a host path (anything\n"
    "with '/', or a single word). Disk L is the directory given by --disk L=DIR, else\n"
    "the environment variable MAPRT_DISK_L; A defaults to the current directory.\n"
    "A file 'fn ft fm' is DIR/fn.ft, matched case-insensitively (new files: lower case).\n"
    "\n"
    "  import   unpack an AWS tape image (CMS TAPE DUMP or VMFPLC2 files) or a punch\n"
    "           deck with :READ cards (ASCII or EBCDIC) onto a disk as host text files;\n"
    "           prints each fileid, RECFM, LRECL and record count.\n"
    "  list     like LISTFILE: fileid, RECFM, LRECL, records and host form of every\n"
    "           file on disk L (default A; '*' = every accessed disk).\n"
    "  type     print a file's records as text lines (trailing blanks removed).\n"
    "  export   write a file in a form a CMS system can read back.\n"
    "\n"
    "options:\n"
    "  --disk L=DIR    disk L is directory DIR (repeatable; overrides MAPRT_DISK_L)\n"
    "  --to L          import: the disk written to (default A)\n"
    "  --tape, --punch import: FILE is an AWS tape / a punch deck (default: detected)\n"
    "  --read-as FORM  read the input as text, punch (text led by a :READ card), ebcdic\n"
    "                  (80-byte EBCDIC cards), vstream (CMS V stream: 2-byte length +\n"
    "                  record) or rdw (z/OS 4-byte RDW stream); default: detected.\n"
    "                  import takes auto, punch or ebcdic\n"
    "  --cp CP         EBCDIC code page, 037 or 1047: of the input for import, list and\n"
    "                  type (default: detected from the bracket and caret codes where they\n"
    "                  decide it, else 1047); of the output for export (default 1047)\n"
    "  --read-cp CP    export: code page of the input (default: detected, as above)\n"
    "  --form FORM     export: text (lines), ebcdic (cards of LRECL bytes, for a Hercules\n"
    "                  reader in ebcdic mode), vstream, or punch (ASCII deck with a :READ\n"
    "                  card, for READCARD); default text\n"
    "  --recfm F|V     export: record format written (default: the input's)\n"
    "  --lrecl N       export: record length written, 1-65535 (default: the input's)\n"
    "\n"
    "Errors carry CMS return codes: 20 invalid character in fileid, 24 invalid\n"
    "filemode, 28 file not found, 36 disk not accessed.\n"
    "Exit status: 0 ok, 1 bad input (incl. those RCs), 2 usage, 3 I/O failure.\n";

static void cms_help_print(FILE *f) { fputs(usage_text, f); }

/* Which options each action takes (bit per option, see opt_names). */
static const char *const opt_names[] = {"--disk", "--read-as", "--form", "--cp", "--read-cp",
                                        "--recfm", "--lrecl", "--to", "--tape", "--punch"};
enum { OPT_DISK = 1, OPT_READ_AS = 2, OPT_FORM = 4, OPT_CP = 8, OPT_READ_CP = 16,
       OPT_RECFM = 32, OPT_LRECL = 64, OPT_TO = 128, OPT_TAPE = 256, OPT_PUNCH = 512 };

static unsigned action_opts(const char *action)
{
    if (!strcmp(action, "import"))
        return OPT_DISK | OPT_READ_AS | OPT_CP | OPT_TO | OPT_TAPE | OPT_PUNCH;
    if (!strcmp(action, "list") || !strcmp(action, "type"))
        return OPT_DISK | OPT_READ_AS | OPT_CP;
    if (!strcmp(action, "export"))
        return OPT_DISK | OPT_READ_AS | OPT_FORM | OPT_CP | OPT_READ_CP | OPT_RECFM | OPT_LRECL;
    return 0;
}

/* Options shared by the subcommands. */
typedef struct cms_cli {
    cms_disks disks;
    const char *pos[3];
    int npos;
    cms_form read_as, form;
    cms_cp_id cp, read_cp;
    int form_set, cp_set, read_cp_set;
    char recfm;
    long lrecl;
    char to;
    cms_import_kind kind;
} cms_cli;

static int cli_fail(const diag *d)
{
    diag_print(stderr, d);
    return d->status ? d->status : CLI_IO;
}

static int parse_cp(const char *opt, const char *v, cms_cp_id *cp)
{
    if (!cms_cp_parse(v, cp))
        return cli_usage_error("cms", "%s: '%s' is not a code page (037 or 1047)", opt, v);
    return 0;
}

/* Parses options after the sub-subcommand into c. */
static int cms_cli_parse(cms_cli *c, int argc, char **argv)
{
    diag d;
    int i;
    diag_init(&d);
    if (cms_disks_from_env(&c->disks, &d))
        return cli_fail(&d);
    for (i = 2; i < argc; i++) {
        const char *a = argv[i], *v;
        unsigned k;
        for (k = 0; k < sizeof opt_names / sizeof opt_names[0]; k++)
            if (!strcmp(a, opt_names[k]) && !(action_opts(argv[1]) & (1u << k)))
                return cli_usage_error("cms", "option %s does not apply to '%s'", a, argv[1]);
        if (!strcmp(a, "--disk") || !strcmp(a, "--read-as") || !strcmp(a, "--form") ||
            !strcmp(a, "--cp") || !strcmp(a, "--read-cp") || !strcmp(a, "--recfm") ||
            !strcmp(a, "--lrecl") || !strcmp(a, "--to")) {
            if (!(v = cli_value("cms", argc, argv, &i)))
                return CLI_USAGE;
            if (!strcmp(a, "--disk")) {
                if (cms_disks_set(&c->disks, v, &d))
                    return d.status == DIAG_USAGE ? cli_usage_error("cms", "%s", d.msg) : cli_fail(&d);
            } else if (!strcmp(a, "--read-as")) {
                if (!cms_form_parse(v, &c->read_as))
                    return cli_usage_error("cms", "--read-as: '%s' is not one of text, punch, ebcdic, vstream, rdw, auto", v);
            } else if (!strcmp(a, "--form")) {
                if (!cms_form_parse(v, &c->form) || c->form == CMS_FORM_AUTO || c->form == CMS_FORM_RDW)
                    return cli_usage_error("cms", "--form: '%s' is not one of text, ebcdic, vstream, punch", v);
                c->form_set = 1;
            } else if (!strcmp(a, "--cp")) {
                if (parse_cp(a, v, &c->cp))
                    return CLI_USAGE;
                c->cp_set = 1;
            } else if (!strcmp(a, "--read-cp")) {
                if (parse_cp(a, v, &c->read_cp))
                    return CLI_USAGE;
                c->read_cp_set = 1;
            } else if (!strcmp(a, "--recfm")) {
                if ((v[0] != 'F' && v[0] != 'V' && v[0] != 'f' && v[0] != 'v') || v[1])
                    return cli_usage_error("cms", "--recfm: '%s' is not F or V", v);
                c->recfm = (char)(v[0] & ~0x20);
            } else if (!strcmp(a, "--lrecl")) {
                if (cli_long("cms", a, v, 1, CMS_LRECL_MAX, &c->lrecl))
                    return CLI_USAGE;
            } else {
                char l = (char)(v[0] & ~0x20);
                if (l < 'A' || l > 'Z' || v[1])
                    return cli_usage_error("cms", "--to: '%s' is not a disk letter", v);
                c->to = l;
            }
        } else if (!strcmp(a, "--tape")) {
            c->kind = CMS_IMPORT_TAPE;
        } else if (!strcmp(a, "--punch")) {
            c->kind = CMS_IMPORT_PUNCH;
        } else if (a[0] == '-' && a[1]) {
            return cli_unknown_option("cms", a, cms_help_print);
        } else {
            if (c->npos == 3)
                return cli_usage_error("cms", "too many arguments ('%s')", a);
            c->pos[c->npos++] = a;
        }
    }
    return 0;
}

static void import_report(void *ctx, const cms_import_item *it)
{
    char t[CMS_FILEID_TEXT_MAX];
    (void)ctx;
    printf("%-20s %c %5ld %8ld records  (%s", cms_fileid_format(&it->id, t, sizeof t),
           it->recfm, it->lrecl, it->records, it->source);
    if (it->cp != CMS_CP_AUTO)
        printf(", code page %03d", (int)it->cp);
    printf(")\n");
}

static int cms_do_import(cms_cli *c)
{
    cms_import_opts o;
    diag d;
    long n = 0;
    int rc;
    if (c->npos != 1)
        return cli_usage_error("cms", "import needs exactly one FILE");
    memset(&o, 0, sizeof o);
    o.kind = c->kind;
    o.form = c->read_as;
    o.cp = c->cp_set ? c->cp : CMS_CP_AUTO;
    o.disk = c->to ? c->to : 'A';
    diag_init(&d);
    /* card decks of any form and tapes; a picture or display list is named */
    if (sniff_refuse(c->pos[0], c->pos[0], 1u << SNIFF_TEXT | 1u << SNIFF_AWS, "a card deck or a tape", &d))
        return cli_fail(&d);
    rc = cms_import(&c->disks, c->pos[0], &o, import_report, NULL, &n, &d);
    if (rc)
        return cli_fail(&d);
    printf("%ld file%s imported to disk %c\n", n, n == 1 ? "" : "s", o.disk);
    return 0;
}

typedef struct list_ctx {
    cms_cli *c;
    int bad;
} list_ctx;

static int list_one(void *ctx, const char *path, const cms_fileid *id)
{
    list_ctx *l = ctx;
    cms_decode_opts o;
    cms_file_info info;
    char t[CMS_FILEID_TEXT_MAX];
    diag d;
    memset(&o, 0, sizeof o);
    o.form = l->c->read_as;
    o.cp = l->c->cp_set ? l->c->cp : CMS_CP_AUTO;
    diag_init(&d);
    if (cms_file_stat(&l->c->disks, path, &o, &info, &d)) {
        sniff_kind k = sniff_file(path);
        if (k != SNIFF_UNKNOWN && k != SNIFF_TEXT) {
            /* a host file that is no CMS file at all: noted, not an error */
            fprintf(stderr, "maprt: note: %s skipped: %s, not a CMS file\n",
                    cms_fileid_format(id, t, sizeof t), sniff_name(k));
            return 0;
        }
        snprintf(d.file, sizeof d.file, "%s", cms_fileid_format(id, t, sizeof t));
        diag_print(stderr, &d);
        l->bad = d.status;
        return 0;
    }
    printf("%-8s %-8s %c%c %c %5ld %8ld  %s\n", id->fn, id->ft, id->mode, id->num,
           info.recfm, info.lrecl, info.records, cms_form_name(info.form));
    return 0;
}

static int cms_do_list(cms_cli *c)
{
    list_ctx l;
    diag d;
    char lo = 'A', hi = 'A', k;
    int listed = 0;
    if (c->npos > 1)
        return cli_usage_error("cms", "list takes at most one disk letter");
    if (c->npos == 1) {
        const char *v = c->pos[0];
        if (!strcmp(v, "*")) {
            lo = 'A';
            hi = 'Z';
        } else if (((v[0] | 0x20) >= 'a' && (v[0] | 0x20) <= 'z') && !v[1])
            lo = hi = (char)(v[0] & ~0x20);
        else
            return cli_usage_error("cms", "list: '%s' is not a disk letter or '*'", v);
    }
    l.c = c;
    l.bad = 0;
    printf("FILENAME FILETYPE FM F LRECL  RECORDS  FORM\n");
    for (k = lo; k <= hi; k++) {
        if (lo != hi && !c->disks.dir[k - 'A'])
            continue;
        diag_init(&d);
        if (cms_disks_list(&c->disks, k, list_one, &l, &d))
            return cli_fail(&d);
        listed++;
    }
    if (!listed) {
        diag_init(&d);
        diag_at(&d, DIAG_INPUT, "* * *", 0, 0, "disk not accessed (RC 36): no disks accessed");
        return cli_fail(&d);
    }
    return l.bad;
}

static int cms_do_type(cms_cli *c)
{
    cms_decode_opts o;
    cms_file *f;
    const char *rec;
    size_t len;
    diag d;
    if (c->npos != 1)
        return cli_usage_error("cms", "type needs exactly one NAME");
    memset(&o, 0, sizeof o);
    o.form = c->read_as;
    o.cp = c->cp_set ? c->cp : CMS_CP_AUTO;
    diag_init(&d);
    if (cms_file_open_read(&f, &c->disks, c->pos[0], &o, &d))
        return cli_fail(&d);
    while (cms_file_read(f, 0, &rec, &len) == 0) {
        while (len && rec[len - 1] == ' ')
            len--;
        fwrite(rec, 1, len, stdout);
        fputc('\n', stdout);
    }
    cms_file_abort(f);
    if (fflush(stdout) != 0) {
        diag_at(&d, DIAG_IO, "<stdout>", 0, 0, "write failed");
        return cli_fail(&d);
    }
    return 0;
}

static int cms_do_export(cms_cli *c)
{
    cms_decode_opts o;
    cms_write_opts w;
    cms_file_info info;
    cms_file *in, *out;
    const char *rec;
    size_t len;
    diag d;
    if (c->npos != 2)
        return cli_usage_error("cms", "export needs NAME and OUT");
    memset(&o, 0, sizeof o);
    o.form = c->read_as;
    o.cp = c->read_cp_set ? c->read_cp : CMS_CP_AUTO;
    diag_init(&d);
    if (cms_file_open_read(&in, &c->disks, c->pos[0], &o, &d))
        return cli_fail(&d);
    cms_file_state(in, &info);
    memset(&w, 0, sizeof w);
    w.form = c->form_set ? c->form : CMS_FORM_TEXT;
    w.cp = c->cp_set ? c->cp : CMS_CP_1047;
    w.header = info.is_fileid ? &info.id : (info.has_header ? &info.header : NULL);
    if (cms_file_open_write(&out, &c->disks, c->pos[1], c->recfm ? c->recfm : info.recfm,
                            c->lrecl ? c->lrecl : (info.lrecl > 0 ? info.lrecl : 80), &w, &d)) {
        cms_file_abort(in);
        return cli_fail(&d);
    }
    while (cms_file_read(in, 0, &rec, &len) == 0)
        if (cms_file_write(out, rec, len, &d)) {
            snprintf(d.file, sizeof d.file, "%s", info.label);
            cms_file_abort(out);
            cms_file_abort(in);
            return cli_fail(&d);
        }
    cms_file_abort(in);
    if (cms_file_close(out, &d))
        return cli_fail(&d);
    return 0;
}

int cmd_cms(int argc, char **argv)
{
    cms_cli c;
    int rc;
    if (cli_wants_help(argc, argv)) {
        fputs(usage_text, stdout);
        return CLI_OK;
    }
    if (argc < 2) {
        fputs(usage_text, stderr);
        return CLI_USAGE;
    }
    if (!action_opts(argv[1]))
        return cli_usage_error("cms", "unknown action '%s' (import, list, type, export)", argv[1]);
    memset(&c, 0, sizeof c);
    cms_disks_init(&c.disks);
    if ((rc = cms_cli_parse(&c, argc, argv)) == 0) {
        if (!strcmp(argv[1], "import"))
            rc = cms_do_import(&c);
        else if (!strcmp(argv[1], "list"))
            rc = cms_do_list(&c);
        else if (!strcmp(argv[1], "type"))
            rc = cms_do_type(&c);
        else
            rc = cms_do_export(&c);
    }
    cms_disks_free(&c.disks);
    return rc;
}
