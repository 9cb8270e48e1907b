/* cmd_cms — `maprt cms import|list|type|export`: the VM/CMS shim from the
 * command line. Moves files between CMS interchange forms (Hercules tapes,
 * punch decks, EBCDIC card images, V streams) and host directories mapped to
 * CMS disks, and shows them the way LISTFILE and TYPE would. */
#include "cli/cli.h"
#include "util/sniff.h"
#include "util/diag.h"
#include "vm_cms_shim/cms_file.h"
#include "vm_cms_shim/cms_import.h"
#include "vm_cms_shim/cms_tape.h"
#include "util/mem.h"
#include "util/outfile.h"
#include <errno.h>
#include <string.h>

static const char usage_text[] =
    "usage: maprt cms import FILE [--to L] [--tape|--punch] [--binary keep|skip|fail] [--replace]\n"
    "                        [--read-as FORM] [--cp CP] [--disk L=DIR ...]\n"
    "       maprt cms list [L|*] [--read-as FORM] [--cp CP] [--disk L=DIR ...]\n"
    "       maprt cms type NAME [--read-as FORM] [--cp CP] [--disk L=DIR ...]\n"
    "       maprt cms export NAME... OUT [--form FORM] [--tape-format vmfplc2|dump]\n"
    "                        [--compress zlib|bzip2] [--userid USER] [--cp CP] [--recfm F|V]\n"
    "                        [--lrecl N] [--read-as FORM] [--read-cp CP] [--disk L=DIR ...]\n"
    "\n"
    "VM/CMS files on the host. NAME and OUT are a CMS fileid such as 'FIG1 SCENE A'\n"
    "(fn ft [fm]; fm defaults to A1, '*' searches disks A..Z) or a host path (anything\n"
    "with '/', or a single word). Disk L is the directory given by --disk L=DIR, else\n"
    "the environment variable MAPRT_DISK_L; A defaults to the current directory.\n"
    "A file 'fn ft fm' is DIR/fn.ft, matched case-insensitively (new files: lower case);\n"
    "DIR/fn.ft.cms, when present, holds its RECFM, LRECL, mode number, date and whether\n"
    "it is binary (then fn.ft is the CMS record stream, byte for byte).\n"
    "\n"
    "  import   unpack an AWS or HET tape image (CMS TAPE DUMP or VMFPLC2 files) or a\n"
    "           punch deck with :READ cards (ASCII or EBCDIC) onto a disk; text files\n"
    "           become host text, binary files keep their records byte for byte. All\n"
    "           or nothing: files are staged and moved into place at the end. Prints\n"
    "           each fileid, RECFM, LRECL and record count.\n"
    "  list     like LISTFILE: fileid, RECFM, LRECL, records and host form of every\n"
    "           file on disk L (default A; '*' = every accessed disk).\n"
    "  type     print a file's records as text lines (trailing blanks removed); a\n"
    "           binary file's records in hexadecimal.\n"
    "  export   write files in a form a CMS system reads back.\n"
    "\n"
    "options:\n"
    "  --disk L=DIR    disk L is directory DIR (repeatable; overrides MAPRT_DISK_L)\n"
    "  --to L          import: the disk written to (default A)\n"
    "  --tape, --punch import: FILE is an AWS/HET tape / a punch deck (default: detected)\n"
    "  --binary MODE   import: a tape file whose records are not text is kept byte for\n"
    "                  byte (keep, the default), left out (skip), or fails the import\n"
    "                  naming its record and column (fail)\n"
    "  --replace       import: replace files that exist on the disk (default: refuse)\n"
    "  --read-as FORM  read the input as text, punch (text led by a :READ card), ebcdic\n"
    "                  (80-byte EBCDIC cards), vstream (CMS V stream: 2-byte length +\n"
    "                  record) or rdw (z/OS 4-byte RDW stream); default: detected.\n"
    "                  import takes auto, punch or ebcdic\n"
    "  --cp CP         EBCDIC code page, 037 or 1047: of the input for import, list and\n"
    "                  type (default: detected from the bracket and caret codes where they\n"
    "                  decide it, else 1047); of the output for export (default 1047)\n"
    "  --read-cp CP    export: code page of the input (default: detected, as above)\n"
    "  --form FORM     export: text (lines), ebcdic (80-byte EBCDIC cards, each record\n"
    "                  padded with blanks; a longer record is refused), vstream, punch\n"
    "                  (ASCII deck with a :READ card, for READCARD), reader (EBCDIC cards\n"
    "                  led by the CP ID card and a :READ card, for the real reader of\n"
    "                  VM/370), aws or het (a tape of one or more files that VMFPLC2 LOAD\n"
    "                  or TAPE LOAD reads); default text\n"
    "  --tape-format F export aws|het: vmfplc2 (default) or dump (CMS TAPE DUMP)\n"
    "  --compress C    export het: zlib (default) or bzip2\n"
    "  --userid USER   export reader: the user whose virtual reader gets the deck\n"
    "  --recfm F|V     export: record format written (default: the input's)\n"
    "  --lrecl N       export: record length written, 1-65535 (default: the input's;\n"
    "                  80 for ebcdic cards)\n"
    "\n"
    "Errors carry CMS return codes: 20 invalid character in fileid, 24 invalid\n"
    "filemode, 28 file not found, 36 disk not accessed.\n"
    "Exit status: 0 ok, 1 bad input (incl. those RCs), 2 usage, 3 I/O failure.\n";

static void cmd_cms_help_print(FILE *f) { fputs(usage_text, f); }

/* Which options each action takes (bit per option, see opt_names); the
 * first CMS_OPT_VALUED take a value. */
static const char *const opt_names[] = {"--disk", "--read-as", "--form", "--cp", "--read-cp",
                                        "--recfm", "--lrecl", "--to", "--binary",
                                        "--tape-format", "--compress", "--userid",
                                        "--tape", "--punch", "--replace"};
#define CMS_OPT_VALUED 12
enum { OPT_DISK = 1, OPT_READ_AS = 2, OPT_FORM = 4, OPT_CP = 8, OPT_READ_CP = 16,
       OPT_RECFM = 32, OPT_LRECL = 64, OPT_TO = 128, OPT_BINARY = 256, OPT_TFORMAT = 512,
       OPT_COMPRESS = 1024, OPT_USERID = 2048, OPT_TAPE = 4096, OPT_PUNCH = 8192,
       OPT_REPLACE = 16384 };

static unsigned cmd_cms_action_opts(const char *action)
{
    if (!strcmp(action, "import"))
        return OPT_DISK | OPT_READ_AS | OPT_CP | OPT_TO | OPT_TAPE | OPT_PUNCH | OPT_BINARY |
               OPT_REPLACE;
    if (!strcmp(action, "list") || !strcmp(action, "type"))
        return OPT_DISK | OPT_READ_AS | OPT_CP;
    if (!strcmp(action, "export"))
        return OPT_DISK | OPT_READ_AS | OPT_FORM | OPT_CP | OPT_READ_CP | OPT_RECFM | OPT_LRECL |
               OPT_TFORMAT | OPT_COMPRESS | OPT_USERID;
    return 0;
}

/* Options shared by the subcommands. */
typedef enum cms_out { OUT_RECORDS = 0, OUT_READER, OUT_AWS, OUT_HET } cms_out;

typedef struct cms_cli {
    cms_disks disks;
    const char **pos;         /* argc entries (owned) */
    int npos;
    cms_out out;
    cms_tape_kind tape_format;
    cms_aws_comp compress;
    cms_binary_policy binary;
    int replace;
    const char *userid;
    cms_form read_as, form;
    cms_cp_id cp, read_cp;
    int form_set, cp_set, read_cp_set;
    char recfm;
    long lrecl;
    char to;
    cms_import_kind kind;
} cms_cli;

static int cmd_cms_cli_fail(const diag *d)
{
    diag_print(stderr, d);
    return d->status ? d->status : CLI_IO;
}

static int cmd_cms_parse_cp(const char *opt, const char *v, cms_cp_id *cp)
{
    if (!cms_cp_parse(v, cp))
        return cli_usage_error("cms", "%s: '%s' is not a code page (037 or 1047)", opt, v);
    return 0;
}

/* Parses options after the sub-subcommand into c. */
static int cmd_cms_cli_parse(cms_cli *c, int argc, char **argv)
{
    diag d;
    int i;
    diag_init(&d);
    if (cms_disks_from_env(&c->disks, &d))
        return cmd_cms_cli_fail(&d);
    for (i = 2; i < argc; i++) {
        const char *a = argv[i], *v;
        unsigned k, known = 0;
        for (k = 0; k < sizeof opt_names / sizeof opt_names[0]; k++)
            if (!strcmp(a, opt_names[k])) {
                if (!(cmd_cms_action_opts(argv[1]) & (1u << k)))
                    return cli_usage_error("cms", "option %s does not apply to '%s'", a, argv[1]);
                known = 1u << k;
            }
        if (known && known < (1u << CMS_OPT_VALUED) && !(v = cli_value("cms", argc, argv, &i)))
            return CLI_USAGE;
        switch (known) {
        case OPT_DISK:
            if (cms_disks_set(&c->disks, v, &d))
                return d.status == DIAG_USAGE ? cli_usage_error("cms", "%s", d.msg) : cmd_cms_cli_fail(&d);
            break;
        case OPT_READ_AS:
            if (!cms_form_parse(v, &c->read_as))
                return cli_usage_error("cms", "--read-as: '%s' is not one of text, punch, ebcdic, vstream, rdw, auto", v);
            break;
        case OPT_FORM:
            if (!strcmp(v, "reader") || !strcmp(v, "aws") || !strcmp(v, "het")) {
                c->out = v[0] == 'r' ? OUT_READER : v[0] == 'a' ? OUT_AWS : OUT_HET;
                c->form = CMS_FORM_EBCDIC;
            } else if (!cms_form_parse(v, &c->form) || c->form == CMS_FORM_AUTO ||
                       c->form == CMS_FORM_RDW) {
                return cli_usage_error("cms", "--form: '%s' is not one of text, ebcdic, vstream, "
                                       "punch, reader, aws, het", v);
            }
            c->form_set = 1;
            break;
        case OPT_CP:
            if (cmd_cms_parse_cp(a, v, &c->cp))
                return CLI_USAGE;
            c->cp_set = 1;
            break;
        case OPT_READ_CP:
            if (cmd_cms_parse_cp(a, v, &c->read_cp))
                return CLI_USAGE;
            c->read_cp_set = 1;
            break;
        case OPT_RECFM:
            if ((v[0] != 'F' && v[0] != 'V' && v[0] != 'f' && v[0] != 'v') || v[1])
                return cli_usage_error("cms", "--recfm: '%s' is not F or V", v);
            c->recfm = (char)(v[0] & ~0x20);
            break;
        case OPT_LRECL:
            if (cli_long("cms", a, v, 1, CMS_LRECL_MAX, &c->lrecl))
                return CLI_USAGE;
            break;
        case OPT_TO: {
            char l = (char)(v[0] & ~0x20);
            if (l < 'A' || l > 'Z' || v[1])
                return cli_usage_error("cms", "--to: '%s' is not a disk letter", v);
            c->to = l;
            break;
        }
        case OPT_BINARY:
            if (!strcmp(v, "keep"))
                c->binary = CMS_BINARY_KEEP;
            else if (!strcmp(v, "skip"))
                c->binary = CMS_BINARY_SKIP;
            else if (!strcmp(v, "fail"))
                c->binary = CMS_BINARY_FAIL;
            else
                return cli_usage_error("cms", "--binary: '%s' is not keep, skip or fail", v);
            break;
        case OPT_TFORMAT:
            if (strcmp(v, "vmfplc2") && strcmp(v, "dump"))
                return cli_usage_error("cms", "--tape-format: '%s' is not vmfplc2 or dump", v);
            c->tape_format = v[0] == 'd' ? CMS_TAPE_DUMP : CMS_TAPE_VMFPLC2;
            break;
        case OPT_COMPRESS:
            if (strcmp(v, "zlib") && strcmp(v, "bzip2"))
                return cli_usage_error("cms", "--compress: '%s' is not zlib or bzip2", v);
            c->compress = v[0] == 'z' ? CMS_AWS_ZLIB : CMS_AWS_BZIP2;
            if (c->compress == CMS_AWS_BZIP2 && !cms_aws_have_bzip2())
                return cli_usage_error("cms", "--compress bzip2: this maprt was built without libbz2 "
                                       "(apt-get install libbz2-dev, then rebuild)");
            break;
        case OPT_USERID: {
            size_t n = strlen(v), j;
            for (j = 0; j < n; j++)
                if (!((v[j] >= 'A' && v[j] <= 'Z') || (v[j] >= 'a' && v[j] <= 'z') ||
                      (v[j] >= '0' && v[j] <= '9') || strchr("$#@", v[j])))
                    break;
            if (n == 0 || n > 8 || j < n)
                return cli_usage_error("cms", "--userid: '%s' is not a VM userid (1-8 letters, "
                                       "digits, $ # @)", v);
            c->userid = v;
            break;
        }
        case OPT_TAPE:
            c->kind = CMS_IMPORT_TAPE;
            break;
        case OPT_PUNCH:
            c->kind = CMS_IMPORT_PUNCH;
            break;
        case OPT_REPLACE:
            c->replace = 1;
            break;
        default:
            if (a[0] == '-' && a[1])
                return cli_unknown_option("cms", a, cmd_cms_help_print);
            c->pos[c->npos++] = a;
        }
    }
    if (c->compress && c->out != OUT_HET)
        return cli_usage_error("cms", "--compress applies to --form het");
    if (c->tape_format && c->out != OUT_AWS && c->out != OUT_HET)
        return cli_usage_error("cms", "--tape-format applies to --form aws and het");
    if ((c->out == OUT_READER) != (c->userid != NULL))
        return cli_usage_error("cms", c->userid ? "--userid applies to --form reader"
                                                : "--form reader needs --userid (the ID card)");
    if (strcmp(argv[1], "export") && c->npos > 3)
        return cli_usage_error("cms", "too many arguments ('%s')", c->pos[3]);
    return 0;
}

/* The decode options list, type and export share. */
static void cmd_cms_cli_decode_opts(const cms_cli *c, cms_decode_opts *o, int set, cms_cp_id cp)
{
    memset(o, 0, sizeof *o);
    o->form = c->read_as;
    o->cp = set ? cp : CMS_CP_AUTO;
}

static void cmd_cms_warn_print(void *ctx, const diag *w)
{
    char buf[1024];
    (void)ctx;
    cms_warn_format(w, buf, sizeof buf);
    fprintf(stderr, "maprt: %s\n", buf);
}

static void cmd_cms_import_report(void *ctx, const cms_import_item *it)
{
    char t[CMS_FILEID_TEXT_MAX];
    (void)ctx;
    printf("%-20s %c %5ld %8ld records  (%s", cms_fileid_format(&it->id, t, sizeof t),
           it->recfm, it->lrecl, it->records, it->source);
    if (it->binary)
        printf(", %s: byte X'%02X' at record %ld column %ld", it->binary == 2 ? "binary, skipped"
               : "binary", it->bin_byte, it->bin_rec, it->bin_col);
    else if (it->cp != CMS_CP_AUTO)
        printf(", code page %03d", (int)it->cp);
    if (it->holes)
        printf(", %ld null block%s", it->holes, it->holes == 1 ? "" : "s");
    if (it->date[0])
        printf(", %s", it->date);
    printf(")\n");
}

static int cmd_cms_do_import(cms_cli *c)
{
    cms_import_opts o;
    cms_warn w;
    diag d;
    long n = 0;
    int rc;
    if (c->npos != 1)
        return cli_usage_error("cms", "import needs exactly one FILE");
    memset(&o, 0, sizeof o);
    w.fn = cmd_cms_warn_print;
    w.ctx = NULL;
    o.kind = c->kind;
    o.form = c->read_as;
    o.cp = c->cp_set ? c->cp : CMS_CP_AUTO;
    o.disk = c->to ? c->to : 'A';
    o.binary = c->binary;
    o.replace = c->replace;
    o.warn = &w;
    diag_init(&d);
    /* card decks of any form and tapes; a picture or display list is named */
    if (sniff_refuse(c->pos[0], c->pos[0], 1u << SNIFF_TEXT | 1u << SNIFF_AWS, "a card deck or a tape", &d))
        return cmd_cms_cli_fail(&d);
    rc = cms_import(&c->disks, c->pos[0], &o, cmd_cms_import_report, NULL, &n, &d);
    if (rc)
        return cmd_cms_cli_fail(&d);
    printf("%ld file%s imported to disk %c\n", n, n == 1 ? "" : "s", o.disk);
    return 0;
}

typedef struct list_ctx {
    cms_cli *c;
    int bad;
} list_ctx;

static int cmd_cms_list_one(void *ctx, const char *path, const cms_fileid *id)
{
    list_ctx *l = ctx;
    cms_decode_opts o;
    cms_file_info info;
    char t[CMS_FILEID_TEXT_MAX];
    diag d;
    cmd_cms_cli_decode_opts(l->c, &o, l->c->cp_set, l->c->cp);
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
    printf("%-8s %-8s %c%c %c %5ld %8ld  %s\n", id->fn, id->ft, id->mode,
           info.id.num ? info.id.num : id->num, info.recfm, info.lrecl, info.records,
           info.binary ? "binary" : cms_form_name(info.form));
    return 0;
}

static int cmd_cms_do_list(cms_cli *c)
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
        if (cms_disks_list(&c->disks, k, cmd_cms_list_one, &l, &d))
            return cmd_cms_cli_fail(&d);
        listed++;
    }
    if (!listed) {
        diag_init(&d);
        diag_at(&d, DIAG_INPUT, "* * *", 0, 0, "disk not accessed (RC 36): no disks accessed");
        return cmd_cms_cli_fail(&d);
    }
    return l.bad;
}

/* A binary record as hex: the record number, then 32 bytes a line in
 * groups of four. */
static void cmd_cms_type_hex(long recno, const char *rec, size_t len)
{
    size_t i;
    printf("%6ld", recno);
    for (i = 0; i < len; i++) {
        if (i && i % 32 == 0)
            printf("\n      ");
        printf("%s%02X", i % 4 == 0 ? " " : "", (unsigned char)rec[i]);
    }
    printf("\n");
}

static int cmd_cms_do_type(cms_cli *c)
{
    cms_decode_opts o;
    cms_file_info info;
    cms_file *f;
    const char *rec;
    size_t len;
    diag d;
    if (c->npos != 1)
        return cli_usage_error("cms", "type needs exactly one NAME");
    cmd_cms_cli_decode_opts(c, &o, c->cp_set, c->cp);
    diag_init(&d);
    if (cms_file_open_read(&f, &c->disks, c->pos[0], &o, &d))
        return cmd_cms_cli_fail(&d);
    cms_file_state(f, &info);
    while (cms_file_read(f, 0, &rec, &len) == 0) {
        if (info.binary) {
            cmd_cms_type_hex(cms_file_recno(f), rec, len);
            continue;
        }
        while (len && rec[len - 1] == ' ')
            len--;
        fwrite(rec, 1, len, stdout);
        fputc('\n', stdout);
    }
    cms_file_abort(f);
    if (fflush(stdout) != 0) {
        diag_at(&d, DIAG_IO, "<stdout>", 0, 0, "write failed");
        return cmd_cms_cli_fail(&d);
    }
    return 0;
}

/* The fileid a file goes to tape (or a :READ card) under: its own fileid,
 * its :READ card's, or a host name of the form fn.ft. */
static int cmd_cms_export_fileid(const cms_file_info *info, cms_fileid *id, diag *d)
{
    const char *base = strrchr(info->label, '/');
    char fn[CMS_NAME_MAX + 1], ft[CMS_NAME_MAX + 1], fm[3] = "A1";
    const char *dot;
    if (info->is_fileid) {
        *id = info->id;
        return 0;
    }
    if (info->has_header) {
        *id = info->header;
        return 0;
    }
    base = base ? base + 1 : info->label;
    dot = strchr(base, '.');
    if (dot && dot > base && (size_t)(dot - base) <= CMS_NAME_MAX && strlen(dot + 1) >= 1 &&
        strlen(dot + 1) <= CMS_NAME_MAX) {
        diag sub;
        memset(fn, ' ', sizeof fn);
        memset(ft, ' ', sizeof ft);
        memcpy(fn, base, (size_t)(dot - base));
        memcpy(ft, dot + 1, strlen(dot + 1));
        diag_init(&sub);
        if (cms_fileid_from_fields(fn, ft, fm, id, &sub) == 0)
            return 0;
    }
    return diag_at(d, DIAG_INPUT, info->label, 0, 0, "no CMS fileid for this file (give it as "
                   "'fn ft fm', or name the host file fn.ft)");
}

static void cmd_cms_export_sink(void *ctx, const void *data, size_t len)
{
    outfile_sink(ctx, data, len);
}

/* export --form aws|het: every NAME as one file of a VMFPLC2 or TAPE DUMP tape. */
static int cmd_cms_export_tape(cms_cli *c, const char *outpath)
{
    cms_name on;
    cms_tape_writer tw;
    outfile of;
    diag d;
    int i, rc;
    diag_init(&d);
    if (cms_name_output(&c->disks, outpath, &on, &d))
        return cmd_cms_cli_fail(&d);
    rc = outfile_open(&of, on.path, &d);
    cms_name_free(&on);
    if (rc)
        return cmd_cms_cli_fail(&d);
    cms_tape_writer_init(&tw, c->tape_format ? c->tape_format : CMS_TAPE_VMFPLC2,
                         c->out == OUT_AWS ? CMS_AWS_PLAIN : c->compress ? c->compress : CMS_AWS_ZLIB,
                         cmd_cms_export_sink, &of);
    for (i = 0; i < c->npos - 1 && !rc; i++) {
        cms_decode_opts o;
        cms_file_info info;
        cms_tape_file tf;
        cms_file *in;
        unsigned char *data = NULL;
        size_t len = 0;
        cmd_cms_cli_decode_opts(c, &o, c->read_cp_set, c->read_cp);
        if ((rc = cms_file_open_read(&in, &c->disks, c->pos[i], &o, &d)))
            break;
        cms_file_state(in, &info);
        memset(&tf, 0, sizeof tf);
        if (!(rc = cmd_cms_export_fileid(&info, &tf.id, &d)))
            rc = cms_file_stream(in, c->cp_set ? c->cp : CMS_CP_1047, &data, &len, &d);
        if (!rc) {
            tf.id.mode = 'A';
            tf.kind = tw.kind;
            tf.recfm = info.recfm;
            tf.lrecl = info.lrecl;
            tf.count = info.records;
            tf.data = data;
            tf.len = len;
            snprintf(tf.date, sizeof tf.date, "%s", info.date);
            if ((rc = cms_tape_write_file(&tw, &tf, &d)) && !d.file[0])
                snprintf(d.file, sizeof d.file, "%s", info.label);
        }
        mem_free(data);
        cms_file_abort(in);
    }
    cms_tape_writer_end(&tw);
    if (rc) {
        outfile_abort(&of);
        return cmd_cms_cli_fail(&d);
    }
    if (outfile_commit(&of, &d))
        return cmd_cms_cli_fail(&d);
    return 0;
}

/* An EBCDIC card from ASCII text (blank-padded to 80 columns). */
static void cmd_cms_export_card(const cms_cp *cp, const char *text, unsigned char card[CMS_CARD_COLS])
{
    size_t i, n = strlen(text);
    for (i = 0; i < CMS_CARD_COLS; i++)
        card[i] = i < n ? cp->from_latin1[(unsigned char)text[i]] : 0x40;
}

static int cmd_cms_do_export(cms_cli *c)
{
    cms_decode_opts o;
    cms_write_opts w;
    cms_file_info info;
    cms_file *in, *out;
    cms_fileid hid;
    const char *rec;
    size_t len;
    char recfm;
    long lrecl;
    diag d;
    if (c->npos < 2)
        return cli_usage_error("cms", "export needs NAME and OUT");
    if (c->out == OUT_AWS || c->out == OUT_HET)
        return cmd_cms_export_tape(c, c->pos[c->npos - 1]);
    if (c->npos != 2)
        return cli_usage_error("cms", "export writes several files only as a tape (--form aws or het)");
    cmd_cms_cli_decode_opts(c, &o, c->read_cp_set, c->read_cp);
    diag_init(&d);
    if (cms_file_open_read(&in, &c->disks, c->pos[0], &o, &d))
        return cmd_cms_cli_fail(&d);
    cms_file_state(in, &info);
    memset(&w, 0, sizeof w);
    w.form = c->form_set ? c->form : CMS_FORM_TEXT;
    w.cp = c->cp_set ? c->cp : CMS_CP_1047;
    w.header = info.is_fileid ? &info.id : (info.has_header ? &info.header : NULL);
    w.binary = info.binary;
    w.date = info.date;
    w.num = info.is_fileid ? info.id.num : 0;
    recfm = c->recfm ? c->recfm : info.recfm;
    lrecl = c->lrecl ? c->lrecl : (info.lrecl > 0 ? info.lrecl : 80);
    if (w.form == CMS_FORM_EBCDIC && !info.binary) {
        /* cards: 80 columns unless --lrecl says otherwise */
        recfm = 'F';
        lrecl = c->lrecl ? c->lrecl : CMS_CARD_COLS;
    }
    if (cms_file_open_write(&out, &c->disks, c->pos[1], recfm, lrecl, &w, &d)) {
        cms_file_abort(in);
        return cmd_cms_cli_fail(&d);
    }
    if (c->out == OUT_READER) {
        /* the CP ID card routes the deck to the user's virtual reader; the
         * :READ card names the file for READCARD */
        const cms_cp *cp;
        char text[CMS_CARD_COLS + 1];
        unsigned char card[CMS_CARD_COLS];
        int rc = cms_cp_get(w.cp, &cp, &d);
        if (!rc && info.binary)
            rc = diag_at(&d, DIAG_INPUT, info.label, 0, 0, "a binary file does not go to a "
                         "reader as cards (write a tape: --form aws or het)");
        if (!rc)
            rc = cmd_cms_export_fileid(&info, &hid, &d);
        if (rc) {
            cms_file_abort(out);
            cms_file_abort(in);
            return cmd_cms_cli_fail(&d);
        }
        snprintf(text, sizeof text, "ID %s", c->userid);
        for (len = 0; text[len]; len++)
            if (text[len] >= 'a' && text[len] <= 'z')
                text[len] = (char)(text[len] - 'a' + 'A');
        cmd_cms_export_card(cp, text, card);
        cms_file_put_raw(out, card, sizeof card);
        snprintf(text, sizeof text, ":READ  %-8s %-8s %c%c", hid.fn, hid.ft, 'A', hid.num);
        cmd_cms_export_card(cp, text, card);
        cms_file_put_raw(out, card, sizeof card);
    }
    while (cms_file_read(in, 0, &rec, &len) == 0)
        if (cms_file_write(out, rec, len, &d)) {
            snprintf(d.file, sizeof d.file, "%s", info.label);
            cms_file_abort(out);
            cms_file_abort(in);
            return cmd_cms_cli_fail(&d);
        }
    cms_file_abort(in);
    if (cms_file_close(out, &d))
        return cmd_cms_cli_fail(&d);
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
    if (!cmd_cms_action_opts(argv[1]))
        return cli_usage_error("cms", "unknown action '%s' (import, list, type, export)", argv[1]);
    memset(&c, 0, sizeof c);
    cms_disks_init(&c.disks);
    if (!(c.pos = mem_calloc((size_t)argc, sizeof *c.pos))) {
        fprintf(stderr, "maprt: error: out of memory\n");
        cms_disks_free(&c.disks);
        return CLI_IO;
    }
    if ((rc = cmd_cms_cli_parse(&c, argc, argv)) == 0) {
        if (!strcmp(argv[1], "import"))
            rc = cmd_cms_do_import(&c);
        else if (!strcmp(argv[1], "list"))
            rc = cmd_cms_do_list(&c);
        else if (!strcmp(argv[1], "type"))
            rc = cmd_cms_do_type(&c);
        else
            rc = cmd_cms_do_export(&c);
    }
    cms_disks_free(&c.disks);
    mem_free(c.pos);
    return rc;
}
