/* test_hfp_hercules — src/num/hfp.c against the Hercules emulator running
 * the real instructions: a third, independent implementation (Hercules
 * 3.13, run as a program; none of its code is in this project).
 *
 * The test writes a storage image holding a small ESA/390 program and
 * seeded random operands, has Hercules (ESA/390 mode, program mask zero:
 * exponent underflow and significance give true zeros without interrupting)
 * load the image, press restart, and save storage back when the program
 * stops.
 * For each operation the program loops over its records: loads the
 * operands, executes the instruction, stores FPR 0, the condition code and
 * the program-interruption code (a program-check handler records it and
 * resumes). Every result is then compared with hfp.c, bit for bit; an
 * interruption must match the exception hfp.c counted (exponent overflow,
 * floating-point divide, square root), whose fixed-up result differs from
 * the hardware's by design (hfp.h).
 *
 * Skipped, with a message, when hercules is not on PATH. MAPRT_HFP_HERC_N
 * sets the operands per instruction (default 20000); runs of more than
 * 50000 go to Hercules in batches. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#include "num/hfp.h"
#include "util/exe.h"
#include "support.h"
#include "hfp_test.h"

#define HERC_DATA 0x10000u         /* records start here */
#define HERC_REC 32                /* op1 8, op2 8, result 8, pic 2, pad 2, IPM word 4 */
#define HERC_BATCH 50000L
#define HERC_CODE 0x400u
#define HERC_TABLE 0xE00u          /* per-op record pointer and count */
#define HERC_DONE 0xFF0u
#define HERC_WAIT 0xFF8u

enum herc_op { H_AER, H_SER, H_MER, H_DER, H_SQER, H_HER, H_CER, H_LRER,
               H_ADR, H_SDR, H_MDR, H_DDR, H_SQDR, H_HDR, H_CDR, H_LRDR, H_N };

static const struct herc_def {
    const char *name;
    unsigned char op[4];   /* the instruction, R1 = 0 and R2 = 2 (LRDR: 4) */
    int len, nd;           /* instruction bytes; operand digits */
} herc_defs[H_N] = {
    [H_AER] = {"AER", {0x3A, 0x02}, 2, 6},   [H_SER] = {"SER", {0x3B, 0x02}, 2, 6},
    [H_MER] = {"MER", {0x3C, 0x02}, 2, 6},   [H_DER] = {"DER", {0x3D, 0x02}, 2, 6},
    [H_SQER] = {"SQER", {0xB2, 0x45, 0x00, 0x02}, 4, 6},
    [H_HER] = {"HER", {0x34, 0x02}, 2, 6},   [H_CER] = {"CER", {0x39, 0x02}, 2, 6},
    [H_LRER] = {"LRER", {0x35, 0x02}, 2, 14},
    [H_ADR] = {"ADR", {0x2A, 0x02}, 2, 14},  [H_SDR] = {"SDR", {0x2B, 0x02}, 2, 14},
    [H_MDR] = {"MDR", {0x2C, 0x02}, 2, 14},  [H_DDR] = {"DDR", {0x2D, 0x02}, 2, 14},
    [H_SQDR] = {"SQDR", {0xB2, 0x44, 0x00, 0x02}, 4, 14},
    [H_HDR] = {"HDR", {0x24, 0x02}, 2, 14},  [H_CDR] = {"CDR", {0x29, 0x02}, 2, 14},
    [H_LRDR] = {"LRDR", {0x25, 0x04}, 2, 14},
};

static void put64(unsigned char *p, uint64_t v)
{
    int i;
    for (i = 0; i < 8; i++)
        p[i] = (unsigned char)(v >> (56 - 8 * i));
}

static uint64_t get64(const unsigned char *p)
{
    uint64_t v = 0;
    int i;
    for (i = 0; i < 8; i++)
        v = v << 8 | p[i];
    return v;
}

static size_t emit(unsigned char *img, size_t at, const char *hex)
{
    while (hex[0] && hex[1]) {
        unsigned v;
        sscanf(hex, "%2x", &v);
        img[at++] = (unsigned char)v;
        hex += 2;
    }
    return at;
}

/* The program: for each op, R6 = its records, R4 = their count; per record
 * R7 -> the interruption-code slot, operands to FPR 0 and 2 (LRDR: the
 * extended operand to FPR 4 and 6), the instruction, IPM, stores. */
static void herc_program(unsigned char *img, long n)
{
    size_t at = HERC_CODE;
    int k;
    char buf[64];
    emit(img, 0x000, "0008000080000400");          /* restart new PSW -> code, 31-bit */
    emit(img, 0x068, "0008000080000300");          /* program new PSW -> handler */
    emit(img, 0x300, "D2017000008E" "82000028");   /* MVC 0(2,7),142; LPSW 40 */
    emit(img, HERC_WAIT, "000A000000000000");      /* disabled wait */
    for (k = 0; k < H_N; k++) {
        uint32_t ptr = HERC_DATA + (uint32_t)(k * n * HERC_REC), tab = HERC_TABLE + 8u * (unsigned)k;
        size_t loop;
        int j;
        img[tab] = (unsigned char)(ptr >> 24); img[tab + 1] = (unsigned char)(ptr >> 16);
        img[tab + 2] = (unsigned char)(ptr >> 8); img[tab + 3] = (unsigned char)ptr;
        img[tab + 4] = (unsigned char)(n >> 24); img[tab + 5] = (unsigned char)(n >> 16);
        img[tab + 6] = (unsigned char)(n >> 8); img[tab + 7] = (unsigned char)n;
        snprintf(buf, sizeof buf, "58600%03X" "58400%03X", tab, tab + 4);   /* L 6; L 4 */
        at = emit(img, at, buf);
        loop = at;
        at = emit(img, at, "41706018");                                    /* LA 7,24(6) */
        at = emit(img, at, k == H_LRDR ? "68406000" "68606008" : "68006000" "68206008");
        for (j = 0; j < herc_defs[k].len; j++)
            img[at++] = herc_defs[k].op[j];
        at = emit(img, at, "B2220080" "5080601C" "60006010" "41606020");  /* IPM; ST; STD; LA */
        snprintf(buf, sizeof buf, "46400%03X", (unsigned)loop);             /* BCT 4,loop */
        at = emit(img, at, buf);
    }
    snprintf(buf, sizeof buf, "92010%03X" "82000%03X", HERC_DONE, HERC_WAIT);
    emit(img, at, buf);
    assert_true(at < HERC_TABLE);
}

static int write_file(const char *dir, const char *name, const void *p, size_t n)
{
    char path[512];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "wb");
    if (!f)
        return -1;
    if (fwrite(p, 1, n, f) != n) {
        fclose(f);
        return -1;
    }
    return fclose(f);
}

/* Runs hercules in dir (which holds h.cnf, hercules.rc, img.bin); 0 ok. */
static int herc_run(const char *dir)
{
    pid_t pid = fork();
    int st, fd;
    if (pid < 0)
        return -1;
    if (pid == 0) {
        if (chdir(dir) != 0)
            _exit(126);
        fd = open("log.txt", O_WRONLY | O_CREAT | O_TRUNC, 0600);
        if (fd >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
        }
        fd = open("/dev/null", O_RDONLY);
        if (fd >= 0)
            dup2(fd, 0);
        execlp("hercules", "hercules", "-f", "h.cnf", (char *)NULL);
        _exit(127);
    }
    if (waitpid(pid, &st, 0) != pid)
        return -1;
    return WIFEXITED(st) && WEXITSTATUS(st) == 0 ? 0 : -1;
}

/* hfp.c's answer for record r of op k: result image (short results in the
 * leading word), condition code for compares, exception kind counted or -1. */
static void herc_ours(int k, const unsigned char *r, uint64_t *res, int *cc, int *exc)
{
    unsigned long before[HFP_EXC_N];
    uint64_t a = get64(r), b = get64(r + 8);
    hfp_short as = (hfp_short)(a >> 32), bs = (hfp_short)(b >> 32);
    int j, c = 0;
    memcpy(before, hfp_exc, sizeof before);
    *res = a;
    switch (k) {
    case H_AER: *res = (uint64_t)hfp_ae(as, bs) << 32 | (a & 0xffffffffu); break;
    case H_SER: *res = (uint64_t)hfp_se(as, bs) << 32 | (a & 0xffffffffu); break;
    case H_MER: *res = hfp_me(as, bs); break;
    case H_DER: *res = (uint64_t)hfp_de(as, bs) << 32 | (a & 0xffffffffu); break;
    case H_SQER: *res = (uint64_t)hfp_sqe(bs) << 32 | (a & 0xffffffffu); break;
    case H_HER: *res = (uint64_t)hfp_her(bs) << 32 | (a & 0xffffffffu); break;
    case H_CER: c = hfp_ce(as, bs); break;
    case H_LRER: *res = (uint64_t)hfp_lrer(b) << 32 | (a & 0xffffffffu); break;
    case H_ADR: *res = hfp_ad(a, b); break;
    case H_SDR: *res = hfp_sd(a, b); break;
    case H_MDR: *res = hfp_md(a, b); break;
    case H_DDR: *res = hfp_dd(a, b); break;
    case H_SQDR: *res = hfp_sqd(b); break;
    case H_HDR: *res = hfp_hdr(b); break;
    case H_CDR: c = hfp_cd(a, b); break;
    case H_LRDR: *res = hfp_lrdr(a, b); break;
    default: break;
    }
    *cc = c < 0 ? 1 : c > 0 ? 2 : 0;
    *exc = -1;
    for (j = 0; j < HFP_EXC_N; j++)
        if (hfp_exc[j] != before[j] && j != HFP_EXC_UNDERFLOW && j != HFP_EXC_SIGNIFICANCE)
            *exc = j;
}

/* One Hercules run of n records per op; adds mismatches to bad[]. */
static void herc_batch(uint64_t *seed, long n, long *bad, long *interrupts)
{
    size_t size = HERC_DATA + (size_t)H_N * (size_t)n * HERC_REC;
    unsigned char *img = calloc(size, 1), *out;
    char dir[] = "/tmp/maprt-hercXXXXXX", rc[512], path[600];
    long i, got;
    int k;
    FILE *f;
    assert_non_null(img);
    assert_non_null(mkdtemp(dir));
    herc_program(img, n);
    for (k = 0; k < H_N; k++)
        for (i = 0; i < n; i++) {
            unsigned char *r = img + HERC_DATA + ((size_t)k * (size_t)n + (size_t)i) * HERC_REC;
            int nd = herc_defs[k].nd;
            uint64_t a = hfp_test_image(seed, nd), b = hfp_test_second(seed, a, nd);
            if (k == H_DER && (test_rand(seed) & 63) == 0)
                b = 0;
            if (nd == 6) {
                a <<= 32;
                b <<= 32;
            }
            if (k == H_LRER)
                b = hfp_test_image(seed, 14);
            put64(r, a);
            put64(r + 8, b);
        }
    /* The automatic operator saves storage once the program has loaded its
     * disabled-wait PSW (retrying while the CPU is still stopping), then
     * quits; the pause is only a time limit. */
    snprintf(rc, sizeof rc,
             "pgmtrace -0C\npgmtrace -0F\npgmtrace -1D\n"
             "hao tgt HHCCP011I\nhao cmd savecore out.bin 0 %lX\n"
             "hao tgt HHCPN102E\nhao cmd savecore out.bin 0 %lX\n"
             "hao tgt HHCPN170I\nhao cmd quit\n"
             "loadcore img.bin 0\nrestart\npause %ld\nquit\n",
             (unsigned long)size - 1, (unsigned long)size - 1, 60 + n / 1000);
    assert_int_equal(write_file(dir, "img.bin", img, size), 0);
    assert_int_equal(write_file(dir, "hercules.rc", rc, strlen(rc)), 0);
    snprintf(path, sizeof path, "ARCHMODE ESA/390\nMAINSIZE %lu\nNUMCPU 1\nCNSLPORT 0\n000E 1403 prt.txt\n",
             (unsigned long)(size >> 20) + 2);
    assert_int_equal(write_file(dir, "h.cnf", path, strlen(path)), 0);
    assert_int_equal(herc_run(dir), 0);
    out = malloc(size);
    assert_non_null(out);
    snprintf(path, sizeof path, "%s/out.bin", dir);
    f = fopen(path, "rb");
    if (!f)
        fail_msg("Hercules saved no storage; see %s/log.txt", dir);
    got = (long)fread(out, 1, size, f);
    fclose(f);
    assert_int_equal(got, (long)size);
    if (out[HERC_DONE] != 1)      /* the program sets it after its last loop */
        fail_msg("Hercules had not finished the program when storage was saved; see %s/log.txt", dir);
    for (k = 0; k < H_N; k++)
        for (i = 0; i < n; i++) {
            const unsigned char *r = out + HERC_DATA + ((size_t)k * (size_t)n + (size_t)i) * HERC_REC;
            uint64_t res, hres = get64(r + 16);
            unsigned pic = (unsigned)r[24] << 8 | r[25];
            int cc, exc, hcc = (r[28] >> 4) & 3, ok;
            herc_ours(k, r, &res, &cc, &exc);
            if (pic)
                (*interrupts)++;
            if (pic == 0x0C)
                ok = exc == HFP_EXC_OVERFLOW;
            else if (pic == 0x0F)
                ok = exc == HFP_EXC_DIVIDE;
            else if (pic == 0x1D)
                ok = exc == HFP_EXC_SQRT;
            else if (pic)
                ok = 0;
            else if (k == H_CER || k == H_CDR)
                ok = exc == -1 && cc == hcc;
            else
                ok = exc == -1 && res == hres;
            if (!ok && bad[k]++ < 3)
                printf("# %s mismatch: op1=%016llx op2=%016llx hercules=%016llx pic=%04x cc=%d, "
                       "hfp.c=%016llx cc=%d exc=%d\n", herc_defs[k].name,
                       (unsigned long long)get64(r), (unsigned long long)get64(r + 8),
                       (unsigned long long)hres, pic, hcc, (unsigned long long)res, cc, exc);
        }
    free(img);
    free(out);
    {
        static const char *const names[] = {"img.bin", "out.bin", "hercules.rc", "h.cnf", "log.txt", "prt.txt"};
        size_t j;
        for (j = 0; j < sizeof names / sizeof names[0]; j++) {
            snprintf(path, sizeof path, "%s/%s", dir, names[j]);
            remove(path);
        }
        rmdir(dir);
    }
}

static void test_hfp_against_hercules(void **state)
{
    uint64_t seed = test_seed("test_hfp_against_hercules");
    long n = hfp_test_count("MAPRT_HFP_HERC_N", 20000), left, bad[H_N] = {0}, interrupts = 0;
    int k, total = 0;
    (void)state;
    if (!exe_on_path("hercules")) {
        printf("# test_hfp_against_hercules: SKIPPED, hercules is not on PATH\n");
        return;
    }
    for (left = n; left > 0; left -= HERC_BATCH)
        herc_batch(&seed, left < HERC_BATCH ? left : HERC_BATCH, bad, &interrupts);
    for (k = 0; k < H_N; k++) {
        printf("# hercules %-5s %ld random operands, %ld mismatches\n", herc_defs[k].name, n, bad[k]);
        total += bad[k] != 0;
    }
    printf("# hercules: %ld program interruptions matched to counted exceptions\n", interrupts);
    assert_int_equal(total, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hfp_against_hercules),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
