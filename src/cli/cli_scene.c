/* cli_scene — file naming and deck loading for the CLI (see cli_scene.h). */
#include "cli/cli_scene.h"
#include "util/sniff.h"
#include "cli/cli.h"
#include "cli/cli_data.h"
#include "image/image_png.h"
#include "scene/scene_parse.h"
#include "util/mem.h"
#include "util/sha256.h"
#include "vm_cms_shim/cms_cp.h"
#include "vm_cms_shim/cms_deck.h"
#include "vm_cms_shim/cms_fileid.h"
#include "vm_cms_shim/cms_name.h"
#include <stdio.h>
#include <string.h>
#include <unistd.h>

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

/* Where a deck's images are found: beside the deck (its host directory),
 * and, for a deck read by fileid, also as fileid "FN FT m" on the deck's
 * disk for an image written FN.FT. */
typedef struct cli_images {
    const cli_files *files;
    char *dir;                 /* the deck's host directory, "" for "." */
    char mode;                 /* the deck's disk letter, 0 for a host path */
} cli_images;

/* A fileid for image name "fn.ft" on disk mode, into out; 0 if the name is
 * not of that form. */
static int cli_scene_images_fileid(const char *name, char mode, char *out, size_t cap)
{
    const char *dot = strchr(name, '.');
    size_t i, fn = dot ? (size_t)(dot - name) : 0, ft = dot ? strlen(dot + 1) : 0;
    if (!mode || !dot || !fn || fn > CMS_NAME_MAX || !ft || ft > CMS_NAME_MAX)
        return 0;
    for (i = 0; name[i]; i++)
        if (i != fn && !cms_fileid_char_ok((unsigned char)name[i]))
            return 0;
    snprintf(out, cap, "%.*s %s %c", (int)fn, name, dot + 1, mode);
    return 1;
}

static int cli_scene_images_read(void *ctx, const char *name, int channels, image *out, diag *err)
{
    const cli_images *im = ctx;
    char fid[3 * CMS_NAME_MAX + 8];
    char *path;
    size_t n;
    int st;
    image_limits lim;
    lim.max_side = IMAGE_MAX_SIDE;
    lim.max_pixels = SCENE_IMAGE_MAX_PIXELS;
    if (name[0] == '/' || !im->dir[0])
        return image_read_png_limit(name, channels, &lim, out, err);
    n = strlen(im->dir) + strlen(name) + 2;
    if (!(path = mem_alloc(n)))
        return diag_at(err, DIAG_IO, name, 0, 0, "out of memory");
    snprintf(path, n, "%s/%s", im->dir, name);
    /* A deck on a CMS disk may name its image by fileid in any case. */
    if (access(path, F_OK) != 0 && cli_scene_images_fileid(name, im->mode, fid, sizeof fid)) {
        cms_name cn;
        diag e2;
        diag_init(&e2);
        if (cms_name_input(&im->files->disks, fid, &cn, &e2) == 0) {
            mem_free(path);
            path = cn.path;
            cn.path = NULL;
            cms_name_free(&cn);
        }
    }
    st = image_read_png_limit(path, channels, &lim, out, err);
    mem_free(path);
    return st;
}

/* Warnings go to stderr as "maprt: FILE:LINE:COL: warning: TEXT". */
static void cli_scene_warn(void *ctx, const diag *w)
{
    (void)ctx;
    diag_print_warning(stderr, w);
}

/* name, or "./name" when a host file of that name exists and the name
 * would otherwise read as a fileid ('my deck' is not 'MY DECK A1' then):
 * into buf, or *owned (mem_free it) when longer. NULL when out of memory. */
static const char *cli_scene_host_first(const char *name, char *buf, size_t cap, char **owned)
{
    size_t n = strlen(name) + 3;
    *owned = NULL;
    if (strchr(name, '/') || access(name, F_OK) != 0 || !cms_fileid_is_fileid(name))
        return name;
    if (n > cap && !(buf = *owned = mem_alloc(n)))
        return NULL;
    snprintf(buf, n, "./%s", name);
    return buf;
}

int cli_scene_load(const cli_files *f, const char *given, scene **out, diag *err)
{
    char sum[65];
    return cli_scene_load_sum(f, given, out, sum, err);
}

int cli_scene_load_sum(const cli_files *f, const char *given, scene **out, char sha256[65], diag *err)
{
    cms_deck *deck;
    recsrc src;
    cms_name cn;
    cli_images im;
    scene_loader ld;
    char *slash, buf[256], *owned, *shipped = NULL;
    const char *name;
    int st;
    if (cli_data_scene(given, &shipped))      /* "fig1": a shipped scene */
        given = shipped;
    name = cli_scene_host_first(given, buf, sizeof buf, &owned);
    st = name ? cms_name_input(&f->disks, name, &cn, err) : diag_at(err, DIAG_IO, given, 0, 0, "out of memory");
    if (st) {
        mem_free(owned);
        mem_free(shipped);
        return st;
    }
    if (sniff_refuse(cn.path, cn.label, 1u << SNIFF_TEXT, "a scene deck", err)) {
        cms_name_free(&cn);
        mem_free(owned);
        mem_free(shipped);
        return err->status;
    }
    im.files = f;
    im.mode = cn.is_fileid ? cn.id.mode : 0;
    im.dir = cn.path;
    cn.path = NULL;
    cms_name_free(&cn);
    slash = strrchr(im.dir, '/');
    if (slash)
        *(slash == im.dir ? slash + 1 : slash) = 0;
    else
        im.dir[0] = 0;
    ld.image = cli_scene_images_read;
    ld.ctx = &im;
    ld.warn = cli_scene_warn;
    st = cms_deck_open(&deck, &src, &f->disks, name, &f->decode, err);
    if (st == 0) {
        cms_file_info info;
        cms_deck_state(deck, &info);
        memcpy(sha256, info.sha256, sizeof info.sha256);
        st = scene_parse_with(&src, &ld, out, err);
        cms_deck_close(deck);
    }
    mem_free(im.dir);
    mem_free(owned);
    mem_free(shipped);
    return st;
}

int cli_output_path(const cli_files *f, const char *given, char **path, diag *err)
{
    cms_name n;
    char buf[256], *owned;
    const char *name = cli_scene_host_first(given, buf, sizeof buf, &owned);
    int st = name ? cms_name_output(&f->disks, name, &n, err)
                  : diag_at(err, DIAG_IO, given, 0, 0, "out of memory");
    mem_free(owned);
    if (st)
        return st;
    *path = n.path;
    n.path = NULL;
    cms_name_free(&n);
    return 0;
}

int cli_file_sha256(const cli_files *f, const char *given, char hex[65], diag *err)
{
    cms_name cn;
    char nbuf[256], buf[4096], *owned, *shipped = NULL;
    const char *name;
    sha256 h;
    FILE *fp;
    size_t n;
    int st;
    if (cli_data_scene(given, &shipped))
        given = shipped;
    name = cli_scene_host_first(given, nbuf, sizeof nbuf, &owned);
    st = name ? cms_name_input(&f->disks, name, &cn, err) : diag_at(err, DIAG_IO, given, 0, 0, "out of memory");
    mem_free(owned);
    mem_free(shipped);
    if (st)
        return st;
    if (!(fp = fopen(cn.path, "rb"))) {
        st = diag_at(err, DIAG_IO, cn.label, 0, 0, "cannot open to checksum it");
        cms_name_free(&cn);
        return st;
    }
    sha256_init(&h);
    while ((n = fread(buf, 1, sizeof buf, fp)) > 0)
        sha256_update(&h, buf, n);
    if (ferror(fp))
        st = diag_at(err, DIAG_IO, cn.label, 0, 0, "read error while checksumming");
    fclose(fp);
    cms_name_free(&cn);
    if (!st)
        sha256_hex(&h, hex);
    return st;
}
