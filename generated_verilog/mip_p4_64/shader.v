module top$lanes$0$shader(clock,value,invalid,at_edge,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag,r,g,b,a,valid);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] value;
    input wire  invalid;
    input wire  at_edge;
    input wire  gx_neg;
    input wire  [31:0] gx_mag;
    input wire  gy_neg;
    input wire  [31:0] gy_mag;
    input wire  gz_neg;
    input wire  [31:0] gz_mag;
    output reg  [31:0] r;
    output reg  [15:0] g;
    output reg  [15:0] b;
    output reg  [15:0] a;
    output reg  valid;
    
    // Constant declarations
    localparam  gm_on = 1'b0;
    localparam  gm_shift = 8'h0;
    localparam  scalar = 1'b1;
    localparam  xray = 1'b0;
    localparam  shaded = 1'b0;
    localparam  edge_transparent = 1'b0;
    localparam  shift = 8'h0;
    localparam  m_max = 16'hff;
    localparam  bit_len$0 = 8'h1;
    localparam  bit_len$1 = 8'h2;
    localparam  bit_len$2 = 8'h3;
    localparam  bit_len$3 = 8'h4;
    localparam  bit_len$4 = 8'h5;
    localparam  bit_len$5 = 8'h6;
    localparam  bit_len$6 = 8'h7;
    localparam  bit_len$7 = 8'h8;
    localparam  bit_len$8 = 8'h9;
    localparam  bit_len$9 = 8'ha;
    localparam  bit_len$10 = 8'hb;
    localparam  bit_len$11 = 8'hc;
    localparam  bit_len$12 = 8'hd;
    localparam  bit_len$13 = 8'he;
    localparam  bit_len$14 = 8'hf;
    localparam  bit_len$15 = 8'h10;
    localparam  bit_len$16 = 8'h11;
    localparam  bit_len$17 = 8'h12;
    localparam  bit_len$18 = 8'h13;
    localparam  bit_len$19 = 8'h14;
    localparam  bit_len$20 = 8'h15;
    localparam  bit_len$21 = 8'h16;
    localparam  bit_len$22 = 8'h17;
    localparam  bit_len$23 = 8'h18;
    localparam  bit_len$24 = 8'h19;
    localparam  bit_len$25 = 8'h1a;
    localparam  bit_len$26 = 8'h1b;
    localparam  bit_len$27 = 8'h1c;
    localparam  bit_len$28 = 8'h1d;
    localparam  bit_len$29 = 8'h1e;
    localparam  bit_len$30 = 8'h1f;
    localparam  bit_len$31 = 8'h20;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [11:0] lut$address;
    wire  [63:0] lut$data = 'h0;
    reg  [14:0] reflectance$address;
    wire  [31:0] reflectance$data = 'h0;
    reg  [15:0] alpha_gm$address;
    wire  [15:0] alpha_gm$data = 'h0;
    reg  [63:0] sqrt$n;
    wire  [31:0] sqrt$root = 'h0;
    reg  [31:0] sq_x$m;
    wire  [63:0] sq_x$y;
    reg  [31:0] sq_y$m;
    wire  [63:0] sq_y$y;
    reg  [31:0] sq_z$m;
    wire  [63:0] sq_z$y;
    reg  [15:0] mul_r$a;
    reg  [15:0] mul_r$b;
    wire  [15:0] mul_r$y = 'h0;
    reg  [15:0] mul_g$a;
    reg  [15:0] mul_g$b;
    wire  [15:0] mul_g$y = 'h0;
    reg  [15:0] mul_b$a;
    reg  [15:0] mul_b$b;
    wire  [15:0] mul_b$y = 'h0;
    reg  [15:0] lit_r$a;
    reg  [15:0] lit_r$b;
    wire  [15:0] lit_r$y = 'h0;
    reg  [15:0] lit_g$a;
    reg  [15:0] lit_g$b;
    wire  [15:0] lit_g$y = 'h0;
    reg  [15:0] lit_b$a;
    reg  [15:0] lit_b$b;
    wire  [15:0] lit_b$y = 'h0;
    reg  [15:0] r_q$d;
    wire  [15:0] r_q$q;
    reg  r_q$clock;
    reg  [15:0] g_q$d;
    wire  [15:0] g_q$q;
    reg  g_q$clock;
    reg  [15:0] b_q$d;
    wire  [15:0] b_q$q;
    reg  b_q$clock;
    reg  [15:0] a_q$d;
    wire  [15:0] a_q$q;
    reg  a_q$clock;
    reg  valid_q$d;
    wire  valid_q$q;
    reg  valid_q$clock;
    
    // Local signals
    reg  [31:0] gm_bin;
    reg  [11:0] row;
    reg  [15:0] alpha;
    reg  [31:0] m;
    reg  [7:0] bl;
    reg  [7:0] s;
    reg  [31:0] half;
    reg  [31:0] qx;
    reg  [31:0] qy;
    reg  [31:0] qz;
    reg  [4:0] ix;
    reg  [4:0] iy;
    reg  [4:0] iz;
    reg  [15:0] diffuse;
    reg  [15:0] specular;
    reg  [31:0] sum_r;
    reg  [31:0] sum_g;
    reg  [31:0] sum_b;
    
    // Sub module instances
    top$lanes$0$shader$sq_x sq_x(
        .m(sq_x$m),
        .y(sq_x$y)
    );
    top$lanes$0$shader$sq_y sq_y(
        .m(sq_y$m),
        .y(sq_y$y)
    );
    top$lanes$0$shader$sq_z sq_z(
        .m(sq_z$m),
        .y(sq_z$y)
    );
    top$lanes$0$shader$r_q r_q(
        .d(r_q$d),
        .q(r_q$q),
        .clock(r_q$clock)
    );
    top$lanes$0$shader$g_q g_q(
        .d(g_q$d),
        .q(g_q$q),
        .clock(g_q$clock)
    );
    top$lanes$0$shader$b_q b_q(
        .d(b_q$d),
        .q(b_q$q),
        .clock(b_q$clock)
    );
    top$lanes$0$shader$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$0$shader$valid_q valid_q(
        .d(valid_q$d),
        .q(valid_q$q),
        .clock(valid_q$clock)
    );
    
    // Update code
    reg  [31:0] r_pass;
    reg  [15:0] g_pass;
    reg  [15:0] b_pass;
    reg  [15:0] a_pass;
    reg  valid_pass;
    always @(*) begin
        r_q$clock = clock;
        g_q$clock = clock;
        b_q$clock = clock;
        a_q$clock = clock;
        valid_q$clock = clock;
        r_q$d = r_q$q;
        g_q$d = g_q$q;
        b_q$d = b_q$q;
        a_q$d = a_q$q;
        valid_q$d = valid_q$q;
        row = 12'(value >> shift);
        lut$address = row;
        alpha = 16'(lut$data >> 'h30);
        sq_x$m = gx_mag;
        sq_y$m = gy_mag;
        sq_z$m = gz_mag;
        sqrt$n = sq_x$y + sq_y$y + sq_z$y;
        gm_bin = sqrt$root >> gm_shift;
        if (gm_bin > 'hf) begin
            gm_bin = 'hf;
        end
        alpha_gm$address = (16'(row) << 'h4) | 16'(gm_bin);
        if (gm_on) begin
            alpha = alpha_gm$data;
        end
        if (invalid | (edge_transparent & at_edge)) begin
            alpha = 'h0;
        end
        m = gx_mag;
        if (gy_mag > m) begin
            m = gy_mag;
        end
        if (gz_mag > m) begin
            m = gz_mag;
        end
        bl = 'h0;
        if (m[0]) begin
            bl = bit_len$0;
        end
        if (m[1]) begin
            bl = bit_len$1;
        end
        if (m[2]) begin
            bl = bit_len$2;
        end
        if (m[3]) begin
            bl = bit_len$3;
        end
        if (m[4]) begin
            bl = bit_len$4;
        end
        if (m[5]) begin
            bl = bit_len$5;
        end
        if (m[6]) begin
            bl = bit_len$6;
        end
        if (m[7]) begin
            bl = bit_len$7;
        end
        if (m[8]) begin
            bl = bit_len$8;
        end
        if (m[9]) begin
            bl = bit_len$9;
        end
        if (m[10]) begin
            bl = bit_len$10;
        end
        if (m[11]) begin
            bl = bit_len$11;
        end
        if (m[12]) begin
            bl = bit_len$12;
        end
        if (m[13]) begin
            bl = bit_len$13;
        end
        if (m[14]) begin
            bl = bit_len$14;
        end
        if (m[15]) begin
            bl = bit_len$15;
        end
        if (m[16]) begin
            bl = bit_len$16;
        end
        if (m[17]) begin
            bl = bit_len$17;
        end
        if (m[18]) begin
            bl = bit_len$18;
        end
        if (m[19]) begin
            bl = bit_len$19;
        end
        if (m[20]) begin
            bl = bit_len$20;
        end
        if (m[21]) begin
            bl = bit_len$21;
        end
        if (m[22]) begin
            bl = bit_len$22;
        end
        if (m[23]) begin
            bl = bit_len$23;
        end
        if (m[24]) begin
            bl = bit_len$24;
        end
        if (m[25]) begin
            bl = bit_len$25;
        end
        if (m[26]) begin
            bl = bit_len$26;
        end
        if (m[27]) begin
            bl = bit_len$27;
        end
        if (m[28]) begin
            bl = bit_len$28;
        end
        if (m[29]) begin
            bl = bit_len$29;
        end
        if (m[30]) begin
            bl = bit_len$30;
        end
        if (m[31]) begin
            bl = bit_len$31;
        end
        s = 'h0;
        if (bl > 'h4) begin
            s = bl - 'h4;
        end
        half = 'h0;
        if (s > 'h0) begin
            half = (32'('h1) << s) >> 'h1;
        end
        qx = (gx_mag + half) >> s;
        if (gx_neg & (s > 'h0)) begin
            qx = (gx_mag + half - 'h1) >> s;
        end
        qy = (gy_mag + half) >> s;
        if (gy_neg & (s > 'h0)) begin
            qy = (gy_mag + half - 'h1) >> s;
        end
        qz = (gz_mag + half) >> s;
        if (gz_neg & (s > 'h0)) begin
            qz = (gz_mag + half - 'h1) >> s;
        end
        if (qx > 'hf) begin
            qx = 'hf;
        end
        if (qy > 'hf) begin
            qy = 'hf;
        end
        if (qz > 'hf) begin
            qz = 'hf;
        end
        ix = 5'(qx);
        if (gx_neg) begin
            ix = 5'('h20 - qx);
        end
        iy = 5'(qy);
        if (gy_neg) begin
            iy = 5'('h20 - qy);
        end
        iz = 5'(qz);
        if (gz_neg) begin
            iz = 5'('h20 - qz);
        end
        reflectance$address = 15'(ix) | (15'(iy) << 'h5) | (15'(iz) << 'ha);
        diffuse = m_max;
        specular = 'h0;
        if (shaded) begin
            diffuse = 16'(reflectance$data);
            specular = 16'(reflectance$data >> 'h10);
        end
        lit_r$a = 16'(lut$data);
        lit_g$a = 16'(lut$data >> 'h10);
        lit_b$a = 16'(lut$data >> 'h20);
        lit_r$b = diffuse;
        lit_g$b = diffuse;
        lit_b$b = diffuse;
        sum_r = 32'(lit_r$y) + 32'(specular);
        sum_g = 32'(lit_g$y) + 32'(specular);
        sum_b = 32'(lit_b$y) + 32'(specular);
        mul_r$a = 16'(sum_r);
        if (sum_r > 32'(m_max)) begin
            mul_r$a = m_max;
        end
        mul_g$a = 16'(sum_g);
        if (sum_g > 32'(m_max)) begin
            mul_g$a = m_max;
        end
        mul_b$a = 16'(sum_b);
        if (sum_b > 32'(m_max)) begin
            mul_b$a = m_max;
        end
        mul_r$b = alpha;
        mul_g$b = alpha;
        mul_b$b = alpha;
        if (scalar) begin
            r_q$d = value;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else if (xray) begin
            r_q$d = alpha;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else begin
            r_q$d = mul_r$y;
            g_q$d = mul_g$y;
            b_q$d = mul_b$y;
            a_q$d = alpha;
        end
        valid_q$d = ~invalid;
        if (xray) begin
            valid_q$d = 1'b1;
        end
        r_pass = 'h0;
        g_pass = 'h0;
        b_pass = 'h0;
        a_pass = 'h0;
        valid_pass = 1'b0;
        if (enabled) begin
            r_pass = 32'(r_q$q);
            g_pass = g_q$q;
            b_pass = b_q$q;
            a_pass = a_q$q;
            valid_pass = valid_q$q;
        end
        r = r_pass;
        g = g_pass;
        b = b_pass;
        a = a_pass;
        valid = valid_pass;
    end
    
endmodule // top$lanes$0$shader
module top$lanes$0$shader$a_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$a_q
module top$lanes$0$shader$b_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$b_q
module top$lanes$0$shader$g_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$g_q
module top$lanes$0$shader$r_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$r_q
module top$lanes$0$shader$sq_x(m,y);
    
    // Module arguments
    input wire  [31:0] m;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [15:0] hi;
    reg  [15:0] lo;
    
    // Update code
    always @(*) begin
        lo = m[('h0)+:(16)];
        hi = 'h0;
        if (wide) begin
            hi = m[('h10)+:(16)];
        end
        y = (64'(hi * hi) << 'h20) + (64'(hi * lo) << 'h11) + 64'(lo * lo);
    end
    
endmodule // top$lanes$0$shader$sq_x
module top$lanes$0$shader$sq_y(m,y);
    
    // Module arguments
    input wire  [31:0] m;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [15:0] hi;
    reg  [15:0] lo;
    
    // Update code
    always @(*) begin
        lo = m[('h0)+:(16)];
        hi = 'h0;
        if (wide) begin
            hi = m[('h10)+:(16)];
        end
        y = (64'(hi * hi) << 'h20) + (64'(hi * lo) << 'h11) + 64'(lo * lo);
    end
    
endmodule // top$lanes$0$shader$sq_y
module top$lanes$0$shader$sq_z(m,y);
    
    // Module arguments
    input wire  [31:0] m;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [15:0] hi;
    reg  [15:0] lo;
    
    // Update code
    always @(*) begin
        lo = m[('h0)+:(16)];
        hi = 'h0;
        if (wide) begin
            hi = m[('h10)+:(16)];
        end
        y = (64'(hi * hi) << 'h20) + (64'(hi * lo) << 'h11) + 64'(lo * lo);
    end
    
endmodule // top$lanes$0$shader$sq_z
module top$lanes$0$shader$valid_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$shader$valid_q
module top$lanes$1$shader(clock,value,invalid,at_edge,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag,r,g,b,a,valid);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] value;
    input wire  invalid;
    input wire  at_edge;
    input wire  gx_neg;
    input wire  [31:0] gx_mag;
    input wire  gy_neg;
    input wire  [31:0] gy_mag;
    input wire  gz_neg;
    input wire  [31:0] gz_mag;
    output reg  [31:0] r;
    output reg  [15:0] g;
    output reg  [15:0] b;
    output reg  [15:0] a;
    output reg  valid;
    
    // Constant declarations
    localparam  gm_on = 1'b0;
    localparam  gm_shift = 8'h0;
    localparam  scalar = 1'b1;
    localparam  xray = 1'b0;
    localparam  shaded = 1'b0;
    localparam  edge_transparent = 1'b0;
    localparam  shift = 8'h0;
    localparam  m_max = 16'hff;
    localparam  bit_len$0 = 8'h1;
    localparam  bit_len$1 = 8'h2;
    localparam  bit_len$2 = 8'h3;
    localparam  bit_len$3 = 8'h4;
    localparam  bit_len$4 = 8'h5;
    localparam  bit_len$5 = 8'h6;
    localparam  bit_len$6 = 8'h7;
    localparam  bit_len$7 = 8'h8;
    localparam  bit_len$8 = 8'h9;
    localparam  bit_len$9 = 8'ha;
    localparam  bit_len$10 = 8'hb;
    localparam  bit_len$11 = 8'hc;
    localparam  bit_len$12 = 8'hd;
    localparam  bit_len$13 = 8'he;
    localparam  bit_len$14 = 8'hf;
    localparam  bit_len$15 = 8'h10;
    localparam  bit_len$16 = 8'h11;
    localparam  bit_len$17 = 8'h12;
    localparam  bit_len$18 = 8'h13;
    localparam  bit_len$19 = 8'h14;
    localparam  bit_len$20 = 8'h15;
    localparam  bit_len$21 = 8'h16;
    localparam  bit_len$22 = 8'h17;
    localparam  bit_len$23 = 8'h18;
    localparam  bit_len$24 = 8'h19;
    localparam  bit_len$25 = 8'h1a;
    localparam  bit_len$26 = 8'h1b;
    localparam  bit_len$27 = 8'h1c;
    localparam  bit_len$28 = 8'h1d;
    localparam  bit_len$29 = 8'h1e;
    localparam  bit_len$30 = 8'h1f;
    localparam  bit_len$31 = 8'h20;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [11:0] lut$address;
    wire  [63:0] lut$data = 'h0;
    reg  [14:0] reflectance$address;
    wire  [31:0] reflectance$data = 'h0;
    reg  [15:0] alpha_gm$address;
    wire  [15:0] alpha_gm$data = 'h0;
    reg  [63:0] sqrt$n;
    wire  [31:0] sqrt$root = 'h0;
    reg  [31:0] sq_x$m;
    wire  [63:0] sq_x$y;
    reg  [31:0] sq_y$m;
    wire  [63:0] sq_y$y;
    reg  [31:0] sq_z$m;
    wire  [63:0] sq_z$y;
    reg  [15:0] mul_r$a;
    reg  [15:0] mul_r$b;
    wire  [15:0] mul_r$y = 'h0;
    reg  [15:0] mul_g$a;
    reg  [15:0] mul_g$b;
    wire  [15:0] mul_g$y = 'h0;
    reg  [15:0] mul_b$a;
    reg  [15:0] mul_b$b;
    wire  [15:0] mul_b$y = 'h0;
    reg  [15:0] lit_r$a;
    reg  [15:0] lit_r$b;
    wire  [15:0] lit_r$y = 'h0;
    reg  [15:0] lit_g$a;
    reg  [15:0] lit_g$b;
    wire  [15:0] lit_g$y = 'h0;
    reg  [15:0] lit_b$a;
    reg  [15:0] lit_b$b;
    wire  [15:0] lit_b$y = 'h0;
    reg  [15:0] r_q$d;
    wire  [15:0] r_q$q;
    reg  r_q$clock;
    reg  [15:0] g_q$d;
    wire  [15:0] g_q$q;
    reg  g_q$clock;
    reg  [15:0] b_q$d;
    wire  [15:0] b_q$q;
    reg  b_q$clock;
    reg  [15:0] a_q$d;
    wire  [15:0] a_q$q;
    reg  a_q$clock;
    reg  valid_q$d;
    wire  valid_q$q;
    reg  valid_q$clock;
    
    // Local signals
    reg  [31:0] gm_bin;
    reg  [11:0] row;
    reg  [15:0] alpha;
    reg  [31:0] m;
    reg  [7:0] bl;
    reg  [7:0] s;
    reg  [31:0] half;
    reg  [31:0] qx;
    reg  [31:0] qy;
    reg  [31:0] qz;
    reg  [4:0] ix;
    reg  [4:0] iy;
    reg  [4:0] iz;
    reg  [15:0] diffuse;
    reg  [15:0] specular;
    reg  [31:0] sum_r;
    reg  [31:0] sum_g;
    reg  [31:0] sum_b;
    
    // Sub module instances
    top$lanes$1$shader$sq_x sq_x(
        .m(sq_x$m),
        .y(sq_x$y)
    );
    top$lanes$1$shader$sq_y sq_y(
        .m(sq_y$m),
        .y(sq_y$y)
    );
    top$lanes$1$shader$sq_z sq_z(
        .m(sq_z$m),
        .y(sq_z$y)
    );
    top$lanes$1$shader$r_q r_q(
        .d(r_q$d),
        .q(r_q$q),
        .clock(r_q$clock)
    );
    top$lanes$1$shader$g_q g_q(
        .d(g_q$d),
        .q(g_q$q),
        .clock(g_q$clock)
    );
    top$lanes$1$shader$b_q b_q(
        .d(b_q$d),
        .q(b_q$q),
        .clock(b_q$clock)
    );
    top$lanes$1$shader$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$1$shader$valid_q valid_q(
        .d(valid_q$d),
        .q(valid_q$q),
        .clock(valid_q$clock)
    );
    
    // Update code
    reg  [31:0] r_pass;
    reg  [15:0] g_pass;
    reg  [15:0] b_pass;
    reg  [15:0] a_pass;
    reg  valid_pass;
    always @(*) begin
        r_q$clock = clock;
        g_q$clock = clock;
        b_q$clock = clock;
        a_q$clock = clock;
        valid_q$clock = clock;
        r_q$d = r_q$q;
        g_q$d = g_q$q;
        b_q$d = b_q$q;
        a_q$d = a_q$q;
        valid_q$d = valid_q$q;
        row = 12'(value >> shift);
        lut$address = row;
        alpha = 16'(lut$data >> 'h30);
        sq_x$m = gx_mag;
        sq_y$m = gy_mag;
        sq_z$m = gz_mag;
        sqrt$n = sq_x$y + sq_y$y + sq_z$y;
        gm_bin = sqrt$root >> gm_shift;
        if (gm_bin > 'hf) begin
            gm_bin = 'hf;
        end
        alpha_gm$address = (16'(row) << 'h4) | 16'(gm_bin);
        if (gm_on) begin
            alpha = alpha_gm$data;
        end
        if (invalid | (edge_transparent & at_edge)) begin
            alpha = 'h0;
        end
        m = gx_mag;
        if (gy_mag > m) begin
            m = gy_mag;
        end
        if (gz_mag > m) begin
            m = gz_mag;
        end
        bl = 'h0;
        if (m[0]) begin
            bl = bit_len$0;
        end
        if (m[1]) begin
            bl = bit_len$1;
        end
        if (m[2]) begin
            bl = bit_len$2;
        end
        if (m[3]) begin
            bl = bit_len$3;
        end
        if (m[4]) begin
            bl = bit_len$4;
        end
        if (m[5]) begin
            bl = bit_len$5;
        end
        if (m[6]) begin
            bl = bit_len$6;
        end
        if (m[7]) begin
            bl = bit_len$7;
        end
        if (m[8]) begin
            bl = bit_len$8;
        end
        if (m[9]) begin
            bl = bit_len$9;
        end
        if (m[10]) begin
            bl = bit_len$10;
        end
        if (m[11]) begin
            bl = bit_len$11;
        end
        if (m[12]) begin
            bl = bit_len$12;
        end
        if (m[13]) begin
            bl = bit_len$13;
        end
        if (m[14]) begin
            bl = bit_len$14;
        end
        if (m[15]) begin
            bl = bit_len$15;
        end
        if (m[16]) begin
            bl = bit_len$16;
        end
        if (m[17]) begin
            bl = bit_len$17;
        end
        if (m[18]) begin
            bl = bit_len$18;
        end
        if (m[19]) begin
            bl = bit_len$19;
        end
        if (m[20]) begin
            bl = bit_len$20;
        end
        if (m[21]) begin
            bl = bit_len$21;
        end
        if (m[22]) begin
            bl = bit_len$22;
        end
        if (m[23]) begin
            bl = bit_len$23;
        end
        if (m[24]) begin
            bl = bit_len$24;
        end
        if (m[25]) begin
            bl = bit_len$25;
        end
        if (m[26]) begin
            bl = bit_len$26;
        end
        if (m[27]) begin
            bl = bit_len$27;
        end
        if (m[28]) begin
            bl = bit_len$28;
        end
        if (m[29]) begin
            bl = bit_len$29;
        end
        if (m[30]) begin
            bl = bit_len$30;
        end
        if (m[31]) begin
            bl = bit_len$31;
        end
        s = 'h0;
        if (bl > 'h4) begin
            s = bl - 'h4;
        end
        half = 'h0;
        if (s > 'h0) begin
            half = (32'('h1) << s) >> 'h1;
        end
        qx = (gx_mag + half) >> s;
        if (gx_neg & (s > 'h0)) begin
            qx = (gx_mag + half - 'h1) >> s;
        end
        qy = (gy_mag + half) >> s;
        if (gy_neg & (s > 'h0)) begin
            qy = (gy_mag + half - 'h1) >> s;
        end
        qz = (gz_mag + half) >> s;
        if (gz_neg & (s > 'h0)) begin
            qz = (gz_mag + half - 'h1) >> s;
        end
        if (qx > 'hf) begin
            qx = 'hf;
        end
        if (qy > 'hf) begin
            qy = 'hf;
        end
        if (qz > 'hf) begin
            qz = 'hf;
        end
        ix = 5'(qx);
        if (gx_neg) begin
            ix = 5'('h20 - qx);
        end
        iy = 5'(qy);
        if (gy_neg) begin
            iy = 5'('h20 - qy);
        end
        iz = 5'(qz);
        if (gz_neg) begin
            iz = 5'('h20 - qz);
        end
        reflectance$address = 15'(ix) | (15'(iy) << 'h5) | (15'(iz) << 'ha);
        diffuse = m_max;
        specular = 'h0;
        if (shaded) begin
            diffuse = 16'(reflectance$data);
            specular = 16'(reflectance$data >> 'h10);
        end
        lit_r$a = 16'(lut$data);
        lit_g$a = 16'(lut$data >> 'h10);
        lit_b$a = 16'(lut$data >> 'h20);
        lit_r$b = diffuse;
        lit_g$b = diffuse;
        lit_b$b = diffuse;
        sum_r = 32'(lit_r$y) + 32'(specular);
        sum_g = 32'(lit_g$y) + 32'(specular);
        sum_b = 32'(lit_b$y) + 32'(specular);
        mul_r$a = 16'(sum_r);
        if (sum_r > 32'(m_max)) begin
            mul_r$a = m_max;
        end
        mul_g$a = 16'(sum_g);
        if (sum_g > 32'(m_max)) begin
            mul_g$a = m_max;
        end
        mul_b$a = 16'(sum_b);
        if (sum_b > 32'(m_max)) begin
            mul_b$a = m_max;
        end
        mul_r$b = alpha;
        mul_g$b = alpha;
        mul_b$b = alpha;
        if (scalar) begin
            r_q$d = value;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else if (xray) begin
            r_q$d = alpha;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else begin
            r_q$d = mul_r$y;
            g_q$d = mul_g$y;
            b_q$d = mul_b$y;
            a_q$d = alpha;
        end
        valid_q$d = ~invalid;
        if (xray) begin
            valid_q$d = 1'b1;
        end
        r_pass = 'h0;
        g_pass = 'h0;
        b_pass = 'h0;
        a_pass = 'h0;
        valid_pass = 1'b0;
        if (enabled) begin
            r_pass = 32'(r_q$q);
            g_pass = g_q$q;
            b_pass = b_q$q;
            a_pass = a_q$q;
            valid_pass = valid_q$q;
        end
        r = r_pass;
        g = g_pass;
        b = b_pass;
        a = a_pass;
        valid = valid_pass;
    end
    
endmodule // top$lanes$1$shader
module top$lanes$1$shader$a_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$a_q
module top$lanes$1$shader$b_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$b_q
module top$lanes$1$shader$g_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$g_q
module top$lanes$1$shader$r_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$r_q
module top$lanes$1$shader$sq_x(m,y);
    
    // Module arguments
    input wire  [31:0] m;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [15:0] hi;
    reg  [15:0] lo;
    
    // Update code
    always @(*) begin
        lo = m[('h0)+:(16)];
        hi = 'h0;
        if (wide) begin
            hi = m[('h10)+:(16)];
        end
        y = (64'(hi * hi) << 'h20) + (64'(hi * lo) << 'h11) + 64'(lo * lo);
    end
    
endmodule // top$lanes$1$shader$sq_x
module top$lanes$1$shader$sq_y(m,y);
    
    // Module arguments
    input wire  [31:0] m;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [15:0] hi;
    reg  [15:0] lo;
    
    // Update code
    always @(*) begin
        lo = m[('h0)+:(16)];
        hi = 'h0;
        if (wide) begin
            hi = m[('h10)+:(16)];
        end
        y = (64'(hi * hi) << 'h20) + (64'(hi * lo) << 'h11) + 64'(lo * lo);
    end
    
endmodule // top$lanes$1$shader$sq_y
module top$lanes$1$shader$sq_z(m,y);
    
    // Module arguments
    input wire  [31:0] m;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [15:0] hi;
    reg  [15:0] lo;
    
    // Update code
    always @(*) begin
        lo = m[('h0)+:(16)];
        hi = 'h0;
        if (wide) begin
            hi = m[('h10)+:(16)];
        end
        y = (64'(hi * hi) << 'h20) + (64'(hi * lo) << 'h11) + 64'(lo * lo);
    end
    
endmodule // top$lanes$1$shader$sq_z
module top$lanes$1$shader$valid_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$shader$valid_q
module top$lanes$2$shader(clock,value,invalid,at_edge,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag,r,g,b,a,valid);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] value;
    input wire  invalid;
    input wire  at_edge;
    input wire  gx_neg;
    input wire  [31:0] gx_mag;
    input wire  gy_neg;
    input wire  [31:0] gy_mag;
    input wire  gz_neg;
    input wire  [31:0] gz_mag;
    output reg  [31:0] r;
    output reg  [15:0] g;
    output reg  [15:0] b;
    output reg  [15:0] a;
    output reg  valid;
    
    // Constant declarations
    localparam  gm_on = 1'b0;
    localparam  gm_shift = 8'h0;
    localparam  scalar = 1'b1;
    localparam  xray = 1'b0;
    localparam  shaded = 1'b0;
    localparam  edge_transparent = 1'b0;
    localparam  shift = 8'h0;
    localparam  m_max = 16'hff;
    localparam  bit_len$0 = 8'h1;
    localparam  bit_len$1 = 8'h2;
    localparam  bit_len$2 = 8'h3;
    localparam  bit_len$3 = 8'h4;
    localparam  bit_len$4 = 8'h5;
    localparam  bit_len$5 = 8'h6;
    localparam  bit_len$6 = 8'h7;
    localparam  bit_len$7 = 8'h8;
    localparam  bit_len$8 = 8'h9;
    localparam  bit_len$9 = 8'ha;
    localparam  bit_len$10 = 8'hb;
    localparam  bit_len$11 = 8'hc;
    localparam  bit_len$12 = 8'hd;
    localparam  bit_len$13 = 8'he;
    localparam  bit_len$14 = 8'hf;
    localparam  bit_len$15 = 8'h10;
    localparam  bit_len$16 = 8'h11;
    localparam  bit_len$17 = 8'h12;
    localparam  bit_len$18 = 8'h13;
    localparam  bit_len$19 = 8'h14;
    localparam  bit_len$20 = 8'h15;
    localparam  bit_len$21 = 8'h16;
    localparam  bit_len$22 = 8'h17;
    localparam  bit_len$23 = 8'h18;
    localparam  bit_len$24 = 8'h19;
    localparam  bit_len$25 = 8'h1a;
    localparam  bit_len$26 = 8'h1b;
    localparam  bit_len$27 = 8'h1c;
    localparam  bit_len$28 = 8'h1d;
    localparam  bit_len$29 = 8'h1e;
    localparam  bit_len$30 = 8'h1f;
    localparam  bit_len$31 = 8'h20;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [11:0] lut$address;
    wire  [63:0] lut$data = 'h0;
    reg  [14:0] reflectance$address;
    wire  [31:0] reflectance$data = 'h0;
    reg  [15:0] alpha_gm$address;
    wire  [15:0] alpha_gm$data = 'h0;
    reg  [63:0] sqrt$n;
    wire  [31:0] sqrt$root = 'h0;
    reg  [31:0] sq_x$m;
    wire  [63:0] sq_x$y;
    reg  [31:0] sq_y$m;
    wire  [63:0] sq_y$y;
    reg  [31:0] sq_z$m;
    wire  [63:0] sq_z$y;
    reg  [15:0] mul_r$a;
    reg  [15:0] mul_r$b;
    wire  [15:0] mul_r$y = 'h0;
    reg  [15:0] mul_g$a;
    reg  [15:0] mul_g$b;
    wire  [15:0] mul_g$y = 'h0;
    reg  [15:0] mul_b$a;
    reg  [15:0] mul_b$b;
    wire  [15:0] mul_b$y = 'h0;
    reg  [15:0] lit_r$a;
    reg  [15:0] lit_r$b;
    wire  [15:0] lit_r$y = 'h0;
    reg  [15:0] lit_g$a;
    reg  [15:0] lit_g$b;
    wire  [15:0] lit_g$y = 'h0;
    reg  [15:0] lit_b$a;
    reg  [15:0] lit_b$b;
    wire  [15:0] lit_b$y = 'h0;
    reg  [15:0] r_q$d;
    wire  [15:0] r_q$q;
    reg  r_q$clock;
    reg  [15:0] g_q$d;
    wire  [15:0] g_q$q;
    reg  g_q$clock;
    reg  [15:0] b_q$d;
    wire  [15:0] b_q$q;
    reg  b_q$clock;
    reg  [15:0] a_q$d;
    wire  [15:0] a_q$q;
    reg  a_q$clock;
    reg  valid_q$d;
    wire  valid_q$q;
    reg  valid_q$clock;
    
    // Local signals
    reg  [31:0] gm_bin;
    reg  [11:0] row;
    reg  [15:0] alpha;
    reg  [31:0] m;
    reg  [7:0] bl;
    reg  [7:0] s;
    reg  [31:0] half;
    reg  [31:0] qx;
    reg  [31:0] qy;
    reg  [31:0] qz;
    reg  [4:0] ix;
    reg  [4:0] iy;
    reg  [4:0] iz;
    reg  [15:0] diffuse;
    reg  [15:0] specular;
    reg  [31:0] sum_r;
    reg  [31:0] sum_g;
    reg  [31:0] sum_b;
    
    // Sub module instances
    top$lanes$2$shader$sq_x sq_x(
        .m(sq_x$m),
        .y(sq_x$y)
    );
    top$lanes$2$shader$sq_y sq_y(
        .m(sq_y$m),
        .y(sq_y$y)
    );
    top$lanes$2$shader$sq_z sq_z(
        .m(sq_z$m),
        .y(sq_z$y)
    );
    top$lanes$2$shader$r_q r_q(
        .d(r_q$d),
        .q(r_q$q),
        .clock(r_q$clock)
    );
    top$lanes$2$shader$g_q g_q(
        .d(g_q$d),
        .q(g_q$q),
        .clock(g_q$clock)
    );
    top$lanes$2$shader$b_q b_q(
        .d(b_q$d),
        .q(b_q$q),
        .clock(b_q$clock)
    );
    top$lanes$2$shader$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$2$shader$valid_q valid_q(
        .d(valid_q$d),
        .q(valid_q$q),
        .clock(valid_q$clock)
    );
    
    // Update code
    reg  [31:0] r_pass;
    reg  [15:0] g_pass;
    reg  [15:0] b_pass;
    reg  [15:0] a_pass;
    reg  valid_pass;
    always @(*) begin
        r_q$clock = clock;
        g_q$clock = clock;
        b_q$clock = clock;
        a_q$clock = clock;
        valid_q$clock = clock;
        r_q$d = r_q$q;
        g_q$d = g_q$q;
        b_q$d = b_q$q;
        a_q$d = a_q$q;
        valid_q$d = valid_q$q;
        row = 12'(value >> shift);
        lut$address = row;
        alpha = 16'(lut$data >> 'h30);
        sq_x$m = gx_mag;
        sq_y$m = gy_mag;
        sq_z$m = gz_mag;
        sqrt$n = sq_x$y + sq_y$y + sq_z$y;
        gm_bin = sqrt$root >> gm_shift;
        if (gm_bin > 'hf) begin
            gm_bin = 'hf;
        end
        alpha_gm$address = (16'(row) << 'h4) | 16'(gm_bin);
        if (gm_on) begin
            alpha = alpha_gm$data;
        end
        if (invalid | (edge_transparent & at_edge)) begin
            alpha = 'h0;
        end
        m = gx_mag;
        if (gy_mag > m) begin
            m = gy_mag;
        end
        if (gz_mag > m) begin
            m = gz_mag;
        end
        bl = 'h0;
        if (m[0]) begin
            bl = bit_len$0;
        end
        if (m[1]) begin
            bl = bit_len$1;
        end
        if (m[2]) begin
            bl = bit_len$2;
        end
        if (m[3]) begin
            bl = bit_len$3;
        end
        if (m[4]) begin
            bl = bit_len$4;
        end
        if (m[5]) begin
            bl = bit_len$5;
        end
        if (m[6]) begin
            bl = bit_len$6;
        end
        if (m[7]) begin
            bl = bit_len$7;
        end
        if (m[8]) begin
            bl = bit_len$8;
        end
        if (m[9]) begin
            bl = bit_len$9;
        end
        if (m[10]) begin
            bl = bit_len$10;
        end
        if (m[11]) begin
            bl = bit_len$11;
        end
        if (m[12]) begin
            bl = bit_len$12;
        end
        if (m[13]) begin
            bl = bit_len$13;
        end
        if (m[14]) begin
            bl = bit_len$14;
        end
        if (m[15]) begin
            bl = bit_len$15;
        end
        if (m[16]) begin
            bl = bit_len$16;
        end
        if (m[17]) begin
            bl = bit_len$17;
        end
        if (m[18]) begin
            bl = bit_len$18;
        end
        if (m[19]) begin
            bl = bit_len$19;
        end
        if (m[20]) begin
            bl = bit_len$20;
        end
        if (m[21]) begin
            bl = bit_len$21;
        end
        if (m[22]) begin
            bl = bit_len$22;
        end
        if (m[23]) begin
            bl = bit_len$23;
        end
        if (m[24]) begin
            bl = bit_len$24;
        end
        if (m[25]) begin
            bl = bit_len$25;
        end
        if (m[26]) begin
            bl = bit_len$26;
        end
        if (m[27]) begin
            bl = bit_len$27;
        end
        if (m[28]) begin
            bl = bit_len$28;
        end
        if (m[29]) begin
            bl = bit_len$29;
        end
        if (m[30]) begin
            bl = bit_len$30;
        end
        if (m[31]) begin
            bl = bit_len$31;
        end
        s = 'h0;
        if (bl > 'h4) begin
            s = bl - 'h4;
        end
        half = 'h0;
        if (s > 'h0) begin
            half = (32'('h1) << s) >> 'h1;
        end
        qx = (gx_mag + half) >> s;
        if (gx_neg & (s > 'h0)) begin
            qx = (gx_mag + half - 'h1) >> s;
        end
        qy = (gy_mag + half) >> s;
        if (gy_neg & (s > 'h0)) begin
            qy = (gy_mag + half - 'h1) >> s;
        end
        qz = (gz_mag + half) >> s;
        if (gz_neg & (s > 'h0)) begin
            qz = (gz_mag + half - 'h1) >> s;
        end
        if (qx > 'hf) begin
            qx = 'hf;
        end
        if (qy > 'hf) begin
            qy = 'hf;
        end
        if (qz > 'hf) begin
            qz = 'hf;
        end
        ix = 5'(qx);
        if (gx_neg) begin
            ix = 5'('h20 - qx);
        end
        iy = 5'(qy);
        if (gy_neg) begin
            iy = 5'('h20 - qy);
        end
        iz = 5'(qz);
        if (gz_neg) begin
            iz = 5'('h20 - qz);
        end
        reflectance$address = 15'(ix) | (15'(iy) << 'h5) | (15'(iz) << 'ha);
        diffuse = m_max;
        specular = 'h0;
        if (shaded) begin
            diffuse = 16'(reflectance$data);
            specular = 16'(reflectance$data >> 'h10);
        end
        lit_r$a = 16'(lut$data);
        lit_g$a = 16'(lut$data >> 'h10);
        lit_b$a = 16'(lut$data >> 'h20);
        lit_r$b = diffuse;
        lit_g$b = diffuse;
        lit_b$b = diffuse;
        sum_r = 32'(lit_r$y) + 32'(specular);
        sum_g = 32'(lit_g$y) + 32'(specular);
        sum_b = 32'(lit_b$y) + 32'(specular);
        mul_r$a = 16'(sum_r);
        if (sum_r > 32'(m_max)) begin
            mul_r$a = m_max;
        end
        mul_g$a = 16'(sum_g);
        if (sum_g > 32'(m_max)) begin
            mul_g$a = m_max;
        end
        mul_b$a = 16'(sum_b);
        if (sum_b > 32'(m_max)) begin
            mul_b$a = m_max;
        end
        mul_r$b = alpha;
        mul_g$b = alpha;
        mul_b$b = alpha;
        if (scalar) begin
            r_q$d = value;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else if (xray) begin
            r_q$d = alpha;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else begin
            r_q$d = mul_r$y;
            g_q$d = mul_g$y;
            b_q$d = mul_b$y;
            a_q$d = alpha;
        end
        valid_q$d = ~invalid;
        if (xray) begin
            valid_q$d = 1'b1;
        end
        r_pass = 'h0;
        g_pass = 'h0;
        b_pass = 'h0;
        a_pass = 'h0;
        valid_pass = 1'b0;
        if (enabled) begin
            r_pass = 32'(r_q$q);
            g_pass = g_q$q;
            b_pass = b_q$q;
            a_pass = a_q$q;
            valid_pass = valid_q$q;
        end
        r = r_pass;
        g = g_pass;
        b = b_pass;
        a = a_pass;
        valid = valid_pass;
    end
    
endmodule // top$lanes$2$shader
module top$lanes$2$shader$a_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$a_q
module top$lanes$2$shader$b_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$b_q
module top$lanes$2$shader$g_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$g_q
module top$lanes$2$shader$r_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$r_q
module top$lanes$2$shader$sq_x(m,y);
    
    // Module arguments
    input wire  [31:0] m;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [15:0] hi;
    reg  [15:0] lo;
    
    // Update code
    always @(*) begin
        lo = m[('h0)+:(16)];
        hi = 'h0;
        if (wide) begin
            hi = m[('h10)+:(16)];
        end
        y = (64'(hi * hi) << 'h20) + (64'(hi * lo) << 'h11) + 64'(lo * lo);
    end
    
endmodule // top$lanes$2$shader$sq_x
module top$lanes$2$shader$sq_y(m,y);
    
    // Module arguments
    input wire  [31:0] m;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [15:0] hi;
    reg  [15:0] lo;
    
    // Update code
    always @(*) begin
        lo = m[('h0)+:(16)];
        hi = 'h0;
        if (wide) begin
            hi = m[('h10)+:(16)];
        end
        y = (64'(hi * hi) << 'h20) + (64'(hi * lo) << 'h11) + 64'(lo * lo);
    end
    
endmodule // top$lanes$2$shader$sq_y
module top$lanes$2$shader$sq_z(m,y);
    
    // Module arguments
    input wire  [31:0] m;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [15:0] hi;
    reg  [15:0] lo;
    
    // Update code
    always @(*) begin
        lo = m[('h0)+:(16)];
        hi = 'h0;
        if (wide) begin
            hi = m[('h10)+:(16)];
        end
        y = (64'(hi * hi) << 'h20) + (64'(hi * lo) << 'h11) + 64'(lo * lo);
    end
    
endmodule // top$lanes$2$shader$sq_z
module top$lanes$2$shader$valid_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$shader$valid_q
module top$lanes$3$shader(clock,value,invalid,at_edge,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag,r,g,b,a,valid);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] value;
    input wire  invalid;
    input wire  at_edge;
    input wire  gx_neg;
    input wire  [31:0] gx_mag;
    input wire  gy_neg;
    input wire  [31:0] gy_mag;
    input wire  gz_neg;
    input wire  [31:0] gz_mag;
    output reg  [31:0] r;
    output reg  [15:0] g;
    output reg  [15:0] b;
    output reg  [15:0] a;
    output reg  valid;
    
    // Constant declarations
    localparam  gm_on = 1'b0;
    localparam  gm_shift = 8'h0;
    localparam  scalar = 1'b1;
    localparam  xray = 1'b0;
    localparam  shaded = 1'b0;
    localparam  edge_transparent = 1'b0;
    localparam  shift = 8'h0;
    localparam  m_max = 16'hff;
    localparam  bit_len$0 = 8'h1;
    localparam  bit_len$1 = 8'h2;
    localparam  bit_len$2 = 8'h3;
    localparam  bit_len$3 = 8'h4;
    localparam  bit_len$4 = 8'h5;
    localparam  bit_len$5 = 8'h6;
    localparam  bit_len$6 = 8'h7;
    localparam  bit_len$7 = 8'h8;
    localparam  bit_len$8 = 8'h9;
    localparam  bit_len$9 = 8'ha;
    localparam  bit_len$10 = 8'hb;
    localparam  bit_len$11 = 8'hc;
    localparam  bit_len$12 = 8'hd;
    localparam  bit_len$13 = 8'he;
    localparam  bit_len$14 = 8'hf;
    localparam  bit_len$15 = 8'h10;
    localparam  bit_len$16 = 8'h11;
    localparam  bit_len$17 = 8'h12;
    localparam  bit_len$18 = 8'h13;
    localparam  bit_len$19 = 8'h14;
    localparam  bit_len$20 = 8'h15;
    localparam  bit_len$21 = 8'h16;
    localparam  bit_len$22 = 8'h17;
    localparam  bit_len$23 = 8'h18;
    localparam  bit_len$24 = 8'h19;
    localparam  bit_len$25 = 8'h1a;
    localparam  bit_len$26 = 8'h1b;
    localparam  bit_len$27 = 8'h1c;
    localparam  bit_len$28 = 8'h1d;
    localparam  bit_len$29 = 8'h1e;
    localparam  bit_len$30 = 8'h1f;
    localparam  bit_len$31 = 8'h20;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  [11:0] lut$address;
    wire  [63:0] lut$data = 'h0;
    reg  [14:0] reflectance$address;
    wire  [31:0] reflectance$data = 'h0;
    reg  [15:0] alpha_gm$address;
    wire  [15:0] alpha_gm$data = 'h0;
    reg  [63:0] sqrt$n;
    wire  [31:0] sqrt$root = 'h0;
    reg  [31:0] sq_x$m;
    wire  [63:0] sq_x$y;
    reg  [31:0] sq_y$m;
    wire  [63:0] sq_y$y;
    reg  [31:0] sq_z$m;
    wire  [63:0] sq_z$y;
    reg  [15:0] mul_r$a;
    reg  [15:0] mul_r$b;
    wire  [15:0] mul_r$y = 'h0;
    reg  [15:0] mul_g$a;
    reg  [15:0] mul_g$b;
    wire  [15:0] mul_g$y = 'h0;
    reg  [15:0] mul_b$a;
    reg  [15:0] mul_b$b;
    wire  [15:0] mul_b$y = 'h0;
    reg  [15:0] lit_r$a;
    reg  [15:0] lit_r$b;
    wire  [15:0] lit_r$y = 'h0;
    reg  [15:0] lit_g$a;
    reg  [15:0] lit_g$b;
    wire  [15:0] lit_g$y = 'h0;
    reg  [15:0] lit_b$a;
    reg  [15:0] lit_b$b;
    wire  [15:0] lit_b$y = 'h0;
    reg  [15:0] r_q$d;
    wire  [15:0] r_q$q;
    reg  r_q$clock;
    reg  [15:0] g_q$d;
    wire  [15:0] g_q$q;
    reg  g_q$clock;
    reg  [15:0] b_q$d;
    wire  [15:0] b_q$q;
    reg  b_q$clock;
    reg  [15:0] a_q$d;
    wire  [15:0] a_q$q;
    reg  a_q$clock;
    reg  valid_q$d;
    wire  valid_q$q;
    reg  valid_q$clock;
    
    // Local signals
    reg  [31:0] gm_bin;
    reg  [11:0] row;
    reg  [15:0] alpha;
    reg  [31:0] m;
    reg  [7:0] bl;
    reg  [7:0] s;
    reg  [31:0] half;
    reg  [31:0] qx;
    reg  [31:0] qy;
    reg  [31:0] qz;
    reg  [4:0] ix;
    reg  [4:0] iy;
    reg  [4:0] iz;
    reg  [15:0] diffuse;
    reg  [15:0] specular;
    reg  [31:0] sum_r;
    reg  [31:0] sum_g;
    reg  [31:0] sum_b;
    
    // Sub module instances
    top$lanes$3$shader$sq_x sq_x(
        .m(sq_x$m),
        .y(sq_x$y)
    );
    top$lanes$3$shader$sq_y sq_y(
        .m(sq_y$m),
        .y(sq_y$y)
    );
    top$lanes$3$shader$sq_z sq_z(
        .m(sq_z$m),
        .y(sq_z$y)
    );
    top$lanes$3$shader$r_q r_q(
        .d(r_q$d),
        .q(r_q$q),
        .clock(r_q$clock)
    );
    top$lanes$3$shader$g_q g_q(
        .d(g_q$d),
        .q(g_q$q),
        .clock(g_q$clock)
    );
    top$lanes$3$shader$b_q b_q(
        .d(b_q$d),
        .q(b_q$q),
        .clock(b_q$clock)
    );
    top$lanes$3$shader$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$lanes$3$shader$valid_q valid_q(
        .d(valid_q$d),
        .q(valid_q$q),
        .clock(valid_q$clock)
    );
    
    // Update code
    reg  [31:0] r_pass;
    reg  [15:0] g_pass;
    reg  [15:0] b_pass;
    reg  [15:0] a_pass;
    reg  valid_pass;
    always @(*) begin
        r_q$clock = clock;
        g_q$clock = clock;
        b_q$clock = clock;
        a_q$clock = clock;
        valid_q$clock = clock;
        r_q$d = r_q$q;
        g_q$d = g_q$q;
        b_q$d = b_q$q;
        a_q$d = a_q$q;
        valid_q$d = valid_q$q;
        row = 12'(value >> shift);
        lut$address = row;
        alpha = 16'(lut$data >> 'h30);
        sq_x$m = gx_mag;
        sq_y$m = gy_mag;
        sq_z$m = gz_mag;
        sqrt$n = sq_x$y + sq_y$y + sq_z$y;
        gm_bin = sqrt$root >> gm_shift;
        if (gm_bin > 'hf) begin
            gm_bin = 'hf;
        end
        alpha_gm$address = (16'(row) << 'h4) | 16'(gm_bin);
        if (gm_on) begin
            alpha = alpha_gm$data;
        end
        if (invalid | (edge_transparent & at_edge)) begin
            alpha = 'h0;
        end
        m = gx_mag;
        if (gy_mag > m) begin
            m = gy_mag;
        end
        if (gz_mag > m) begin
            m = gz_mag;
        end
        bl = 'h0;
        if (m[0]) begin
            bl = bit_len$0;
        end
        if (m[1]) begin
            bl = bit_len$1;
        end
        if (m[2]) begin
            bl = bit_len$2;
        end
        if (m[3]) begin
            bl = bit_len$3;
        end
        if (m[4]) begin
            bl = bit_len$4;
        end
        if (m[5]) begin
            bl = bit_len$5;
        end
        if (m[6]) begin
            bl = bit_len$6;
        end
        if (m[7]) begin
            bl = bit_len$7;
        end
        if (m[8]) begin
            bl = bit_len$8;
        end
        if (m[9]) begin
            bl = bit_len$9;
        end
        if (m[10]) begin
            bl = bit_len$10;
        end
        if (m[11]) begin
            bl = bit_len$11;
        end
        if (m[12]) begin
            bl = bit_len$12;
        end
        if (m[13]) begin
            bl = bit_len$13;
        end
        if (m[14]) begin
            bl = bit_len$14;
        end
        if (m[15]) begin
            bl = bit_len$15;
        end
        if (m[16]) begin
            bl = bit_len$16;
        end
        if (m[17]) begin
            bl = bit_len$17;
        end
        if (m[18]) begin
            bl = bit_len$18;
        end
        if (m[19]) begin
            bl = bit_len$19;
        end
        if (m[20]) begin
            bl = bit_len$20;
        end
        if (m[21]) begin
            bl = bit_len$21;
        end
        if (m[22]) begin
            bl = bit_len$22;
        end
        if (m[23]) begin
            bl = bit_len$23;
        end
        if (m[24]) begin
            bl = bit_len$24;
        end
        if (m[25]) begin
            bl = bit_len$25;
        end
        if (m[26]) begin
            bl = bit_len$26;
        end
        if (m[27]) begin
            bl = bit_len$27;
        end
        if (m[28]) begin
            bl = bit_len$28;
        end
        if (m[29]) begin
            bl = bit_len$29;
        end
        if (m[30]) begin
            bl = bit_len$30;
        end
        if (m[31]) begin
            bl = bit_len$31;
        end
        s = 'h0;
        if (bl > 'h4) begin
            s = bl - 'h4;
        end
        half = 'h0;
        if (s > 'h0) begin
            half = (32'('h1) << s) >> 'h1;
        end
        qx = (gx_mag + half) >> s;
        if (gx_neg & (s > 'h0)) begin
            qx = (gx_mag + half - 'h1) >> s;
        end
        qy = (gy_mag + half) >> s;
        if (gy_neg & (s > 'h0)) begin
            qy = (gy_mag + half - 'h1) >> s;
        end
        qz = (gz_mag + half) >> s;
        if (gz_neg & (s > 'h0)) begin
            qz = (gz_mag + half - 'h1) >> s;
        end
        if (qx > 'hf) begin
            qx = 'hf;
        end
        if (qy > 'hf) begin
            qy = 'hf;
        end
        if (qz > 'hf) begin
            qz = 'hf;
        end
        ix = 5'(qx);
        if (gx_neg) begin
            ix = 5'('h20 - qx);
        end
        iy = 5'(qy);
        if (gy_neg) begin
            iy = 5'('h20 - qy);
        end
        iz = 5'(qz);
        if (gz_neg) begin
            iz = 5'('h20 - qz);
        end
        reflectance$address = 15'(ix) | (15'(iy) << 'h5) | (15'(iz) << 'ha);
        diffuse = m_max;
        specular = 'h0;
        if (shaded) begin
            diffuse = 16'(reflectance$data);
            specular = 16'(reflectance$data >> 'h10);
        end
        lit_r$a = 16'(lut$data);
        lit_g$a = 16'(lut$data >> 'h10);
        lit_b$a = 16'(lut$data >> 'h20);
        lit_r$b = diffuse;
        lit_g$b = diffuse;
        lit_b$b = diffuse;
        sum_r = 32'(lit_r$y) + 32'(specular);
        sum_g = 32'(lit_g$y) + 32'(specular);
        sum_b = 32'(lit_b$y) + 32'(specular);
        mul_r$a = 16'(sum_r);
        if (sum_r > 32'(m_max)) begin
            mul_r$a = m_max;
        end
        mul_g$a = 16'(sum_g);
        if (sum_g > 32'(m_max)) begin
            mul_g$a = m_max;
        end
        mul_b$a = 16'(sum_b);
        if (sum_b > 32'(m_max)) begin
            mul_b$a = m_max;
        end
        mul_r$b = alpha;
        mul_g$b = alpha;
        mul_b$b = alpha;
        if (scalar) begin
            r_q$d = value;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else if (xray) begin
            r_q$d = alpha;
            g_q$d = 'h0;
            b_q$d = 'h0;
            a_q$d = 'h0;
        end
        else begin
            r_q$d = mul_r$y;
            g_q$d = mul_g$y;
            b_q$d = mul_b$y;
            a_q$d = alpha;
        end
        valid_q$d = ~invalid;
        if (xray) begin
            valid_q$d = 1'b1;
        end
        r_pass = 'h0;
        g_pass = 'h0;
        b_pass = 'h0;
        a_pass = 'h0;
        valid_pass = 1'b0;
        if (enabled) begin
            r_pass = 32'(r_q$q);
            g_pass = g_q$q;
            b_pass = b_q$q;
            a_pass = a_q$q;
            valid_pass = valid_q$q;
        end
        r = r_pass;
        g = g_pass;
        b = b_pass;
        a = a_pass;
        valid = valid_pass;
    end
    
endmodule // top$lanes$3$shader
module top$lanes$3$shader$a_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$a_q
module top$lanes$3$shader$b_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$b_q
module top$lanes$3$shader$g_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$g_q
module top$lanes$3$shader$r_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$r_q
module top$lanes$3$shader$sq_x(m,y);
    
    // Module arguments
    input wire  [31:0] m;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [15:0] hi;
    reg  [15:0] lo;
    
    // Update code
    always @(*) begin
        lo = m[('h0)+:(16)];
        hi = 'h0;
        if (wide) begin
            hi = m[('h10)+:(16)];
        end
        y = (64'(hi * hi) << 'h20) + (64'(hi * lo) << 'h11) + 64'(lo * lo);
    end
    
endmodule // top$lanes$3$shader$sq_x
module top$lanes$3$shader$sq_y(m,y);
    
    // Module arguments
    input wire  [31:0] m;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [15:0] hi;
    reg  [15:0] lo;
    
    // Update code
    always @(*) begin
        lo = m[('h0)+:(16)];
        hi = 'h0;
        if (wide) begin
            hi = m[('h10)+:(16)];
        end
        y = (64'(hi * hi) << 'h20) + (64'(hi * lo) << 'h11) + 64'(lo * lo);
    end
    
endmodule // top$lanes$3$shader$sq_y
module top$lanes$3$shader$sq_z(m,y);
    
    // Module arguments
    input wire  [31:0] m;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [15:0] hi;
    reg  [15:0] lo;
    
    // Update code
    always @(*) begin
        lo = m[('h0)+:(16)];
        hi = 'h0;
        if (wide) begin
            hi = m[('h10)+:(16)];
        end
        y = (64'(hi * hi) << 'h20) + (64'(hi * lo) << 'h11) + 64'(lo * lo);
    end
    
endmodule // top$lanes$3$shader$sq_z
module top$lanes$3$shader$valid_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$shader$valid_q
