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
    localparam  scalar = 1'b0;
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
    wire  [63:0] lut$data;
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
    wire  [15:0] mul_r$y;
    reg  [15:0] mul_g$a;
    reg  [15:0] mul_g$b;
    wire  [15:0] mul_g$y;
    reg  [15:0] mul_b$a;
    reg  [15:0] mul_b$b;
    wire  [15:0] mul_b$y;
    reg  [15:0] lit_r$a;
    reg  [15:0] lit_r$b;
    wire  [15:0] lit_r$y;
    reg  [15:0] lit_g$a;
    reg  [15:0] lit_g$b;
    wire  [15:0] lit_g$y;
    reg  [15:0] lit_b$a;
    reg  [15:0] lit_b$b;
    wire  [15:0] lit_b$y;
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
    top$lanes$0$shader$lut lut(
        .address(lut$address),
        .data(lut$data)
    );
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
    top$lanes$0$shader$mul_r mul_r(
        .a(mul_r$a),
        .b(mul_r$b),
        .y(mul_r$y)
    );
    top$lanes$0$shader$mul_g mul_g(
        .a(mul_g$a),
        .b(mul_g$b),
        .y(mul_g$y)
    );
    top$lanes$0$shader$mul_b mul_b(
        .a(mul_b$a),
        .b(mul_b$b),
        .y(mul_b$y)
    );
    top$lanes$0$shader$lit_r lit_r(
        .a(lit_r$a),
        .b(lit_r$b),
        .y(lit_r$y)
    );
    top$lanes$0$shader$lit_g lit_g(
        .a(lit_g$a),
        .b(lit_g$b),
        .y(lit_g$y)
    );
    top$lanes$0$shader$lit_b lit_b(
        .a(lit_b$a),
        .b(lit_b$b),
        .y(lit_b$y)
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
module top$lanes$0$shader$lit_b(a,b,y);
    
    // Module arguments
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [31:0] t;
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t = a * b + half;
        y_pass = 16'((t + (t >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$0$shader$lit_b
module top$lanes$0$shader$lit_g(a,b,y);
    
    // Module arguments
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [31:0] t;
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t = a * b + half;
        y_pass = 16'((t + (t >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$0$shader$lit_g
module top$lanes$0$shader$lit_r(a,b,y);
    
    // Module arguments
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [31:0] t;
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t = a * b + half;
        y_pass = 16'((t + (t >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$0$shader$lit_r
module top$lanes$0$shader$lut(address,data);
    
    // Module arguments
    input wire  [11:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        12'h0: data = 64'h80009900e6;
      12'h1: data = 64'h7f009900e6;
      12'h2: data = 64'h7f009800e6;
      12'h3: data = 64'h7f009800e6;
      12'h4: data = 64'h7e009800e6;
      12'h5: data = 64'h7e009700e6;
      12'h6: data = 64'h7e009700e6;
      12'h7: data = 64'h7d009700e6;
      12'h8: data = 64'h7d009600e6;
      12'h9: data = 64'h7d009600e6;
      12'ha: data = 64'h7c009600e7;
      12'hb: data = 64'h7c009500e7;
      12'hc: data = 64'h7c009500e7;
      12'hd: data = 64'h7b009500e7;
      12'he: data = 64'h7b009500e7;
      12'hf: data = 64'h7b009400e7;
      12'h10: data = 64'h7a009400e7;
      12'h11: data = 64'h7a009400e7;
      12'h12: data = 64'h7a009300e7;
      12'h13: data = 64'h79009300e8;
      12'h14: data = 64'h79009300e8;
      12'h15: data = 64'h79009200e8;
      12'h16: data = 64'h78009200e8;
      12'h17: data = 64'h78009200e8;
      12'h18: data = 64'h78009100e8;
      12'h19: data = 64'h78009100e8;
      12'h1a: data = 64'h77009100e8;
      12'h1b: data = 64'h77009000e8;
      12'h1c: data = 64'h77009000e8;
      12'h1d: data = 64'h76009000e9;
      12'h1e: data = 64'h76008f00e9;
      12'h1f: data = 64'h76008f00e9;
      12'h20: data = 64'h75008f00e9;
      12'h21: data = 64'h75008e00e9;
      12'h22: data = 64'h75008e00e9;
      12'h23: data = 64'h74008e00e9;
      12'h24: data = 64'h74008e00e9;
      12'h25: data = 64'h74008d00e9;
      12'h26: data = 64'h73008d00ea;
      12'h27: data = 64'h73008d00ea;
      12'h28: data = 64'h73008c00ea;
      12'h29: data = 64'h72008c00ea;
      12'h2a: data = 64'h72008c00ea;
      12'h2b: data = 64'h72008b00ea;
      12'h2c: data = 64'h71008b00ea;
      12'h2d: data = 64'h71008b00ea;
      12'h2e: data = 64'h71008a00ea;
      12'h2f: data = 64'h71008a00ea;
      12'h30: data = 64'h70008a00eb;
      12'h31: data = 64'h70008900eb;
      12'h32: data = 64'h70008900eb;
      12'h33: data = 64'h6f008900eb;
      12'h34: data = 64'h6f008800eb;
      12'h35: data = 64'h6f008800eb;
      12'h36: data = 64'h6e008800eb;
      12'h37: data = 64'h6e008700eb;
      12'h38: data = 64'h6e008700eb;
      12'h39: data = 64'h6d008700ec;
      12'h3a: data = 64'h6d008700ec;
      12'h3b: data = 64'h6d008600ec;
      12'h3c: data = 64'h6c008600ec;
      12'h3d: data = 64'h1006c008600ec;
      12'h3e: data = 64'h2006c008500ec;
      12'h3f: data = 64'h3006b008500ec;
      12'h40: data = 64'h3006b008500ec;
      12'h41: data = 64'h4006b008400ec;
      12'h42: data = 64'h5006a008400ed;
      12'h43: data = 64'h6006a008400ed;
      12'h44: data = 64'h7006a008300ed;
      12'h45: data = 64'h8006a008300ed;
      12'h46: data = 64'h90069008300ed;
      12'h47: data = 64'h90069008200ed;
      12'h48: data = 64'ha0069008200ed;
      12'h49: data = 64'hb0068008200ed;
      12'h4a: data = 64'hc0068008100ed;
      12'h4b: data = 64'hd0068008100ed;
      12'h4c: data = 64'he0067008100ee;
      12'h4d: data = 64'hf0067008000ee;
      12'h4e: data = 64'hf0067008000ee;
      12'h4f: data = 64'h100066008000ee;
      12'h50: data = 64'h110066008000ee;
      12'h51: data = 64'h120066007f00ee;
      12'h52: data = 64'h130065007f00ee;
      12'h53: data = 64'h150065007f00ee;
      12'h54: data = 64'h160065007e00ee;
      12'h55: data = 64'h170064007e00ef;
      12'h56: data = 64'h180064007e00ef;
      12'h57: data = 64'h1a0064007d00ef;
      12'h58: data = 64'h1b0063007d00ef;
      12'h59: data = 64'h1c0063007d00ef;
      12'h5a: data = 64'h1d0063007c00ef;
      12'h5b: data = 64'h1e0062007c00ef;
      12'h5c: data = 64'h1f0062007c00ef;
      12'h5d: data = 64'h210062007b00ef;
      12'h5e: data = 64'h220062007b00ef;
      12'h5f: data = 64'h230061007b00f0;
      12'h60: data = 64'h240061007a00f0;
      12'h61: data = 64'h250061007a00f0;
      12'h62: data = 64'h270060007a00f0;
      12'h63: data = 64'h280060007900f0;
      12'h64: data = 64'h290060007900f0;
      12'h65: data = 64'h2a005f007900f0;
      12'h66: data = 64'h2b005f007800f0;
      12'h67: data = 64'h2c005f007800f0;
      12'h68: data = 64'h2e005e007800f1;
      12'h69: data = 64'h2f005e007800f1;
      12'h6a: data = 64'h30005e007700f1;
      12'h6b: data = 64'h31005d007700f1;
      12'h6c: data = 64'h32005d007700f1;
      12'h6d: data = 64'h33005d007600f1;
      12'h6e: data = 64'h35005c007600f1;
      12'h6f: data = 64'h36005c007600f1;
      12'h70: data = 64'h37005c007500f1;
      12'h71: data = 64'h38005b007500f2;
      12'h72: data = 64'h39005b007500f2;
      12'h73: data = 64'h3a005b007400f2;
      12'h74: data = 64'h3c005b007400f2;
      12'h75: data = 64'h3d005a007400f2;
      12'h76: data = 64'h3e005a007300f2;
      12'h77: data = 64'h3f005a007300f2;
      12'h78: data = 64'h400059007300f2;
      12'h79: data = 64'h41005a007500f2;
      12'h7a: data = 64'h42005b007700f3;
      12'h7b: data = 64'h44005b007800f3;
      12'h7c: data = 64'h45005c007a00f3;
      12'h7d: data = 64'h46005c007c00f3;
      12'h7e: data = 64'h47005d007e00f4;
      12'h7f: data = 64'h48005e008000f4;
      12'h80: data = 64'h49005e008200f4;
      12'h81: data = 64'h4a005f008400f4;
      12'h82: data = 64'h4b0060008600f4;
      12'h83: data = 64'h4d0060008800f5;
      12'h84: data = 64'h4e0061008a00f5;
      12'h85: data = 64'h4f0062008c00f5;
      12'h86: data = 64'h500062008e00f5;
      12'h87: data = 64'h510063008f00f5;
      12'h88: data = 64'h520063009100f6;
      12'h89: data = 64'h530064009300f6;
      12'h8a: data = 64'h540065009500f6;
      12'h8b: data = 64'h550065009700f6;
      12'h8c: data = 64'h570066009900f7;
      12'h8d: data = 64'h580067009b00f7;
      12'h8e: data = 64'h590067009d00f7;
      12'h8f: data = 64'h5a0068009f00f7;
      12'h90: data = 64'h5b006900a100f7;
      12'h91: data = 64'h5c006900a300f8;
      12'h92: data = 64'h5d006a00a400f8;
      12'h93: data = 64'h5e006a00a600f8;
      12'h94: data = 64'h5f006b00a800f8;
      12'h95: data = 64'h60006c00aa00f8;
      12'h96: data = 64'h62006c00ac00f9;
      12'h97: data = 64'h63006d00ae00f9;
      12'h98: data = 64'h65006e00b000f9;
      12'h99: data = 64'h67006e00b200f9;
      12'h9a: data = 64'h69006f00b400f9;
      12'h9b: data = 64'h6b007000b600fa;
      12'h9c: data = 64'h6c007000b800fa;
      12'h9d: data = 64'h6e007100ba00fa;
      12'h9e: data = 64'h70007100bb00fa;
      12'h9f: data = 64'h72007200bd00fb;
      12'ha0: data = 64'h74007300bf00fb;
      12'ha1: data = 64'h75007300c100fb;
      12'ha2: data = 64'h77007400c300fb;
      12'ha3: data = 64'h79007500c500fb;
      12'ha4: data = 64'h7b007500c700fc;
      12'ha5: data = 64'h7c007600c900fc;
      12'ha6: data = 64'h7e007700cb00fc;
      12'ha7: data = 64'h80007700cd00fc;
      12'ha8: data = 64'h81007800cf00fc;
      12'ha9: data = 64'h83007800d000fd;
      12'haa: data = 64'h85007900d200fd;
      12'hab: data = 64'h87007a00d400fd;
      12'hac: data = 64'h88007a00d600fd;
      12'had: data = 64'h8a007b00d800fe;
      12'hae: data = 64'h8c007c00da00fe;
      12'haf: data = 64'h8d007c00dc00fe;
      12'hb0: data = 64'h8f007d00de00fe;
      12'hb1: data = 64'h91007e00e000fe;
      12'hb2: data = 64'h92007e00e200ff;
      12'hb3: data = 64'h94007f00e400ff;
      12'hb4: data = 64'h96008000e600ff;
      12'hb5: data = 64'h97008100e600ff;
      12'hb6: data = 64'h99008300e600ff;
      12'hb7: data = 64'h9b008400e700ff;
      12'hb8: data = 64'h9c008600e700ff;
      12'hb9: data = 64'h9e008700e700ff;
      12'hba: data = 64'h9f008900e800ff;
      12'hbb: data = 64'ha1008a00e800ff;
      12'hbc: data = 64'ha3008c00e800ff;
      12'hbd: data = 64'ha4008d00e900ff;
      12'hbe: data = 64'ha6008f00e900ff;
      12'hbf: data = 64'ha7009000e900ff;
      12'hc0: data = 64'ha9009200ea00ff;
      12'hc1: data = 64'haa009300ea00ff;
      12'hc2: data = 64'hac009500ea00ff;
      12'hc3: data = 64'hae009600eb00ff;
      12'hc4: data = 64'haf009800eb00ff;
      12'hc5: data = 64'hb1009a00eb00ff;
      12'hc6: data = 64'hb2009b00ec00ff;
      12'hc7: data = 64'hb4009d00ec00ff;
      12'hc8: data = 64'hb5009e00ec00ff;
      12'hc9: data = 64'hb600a000ed00ff;
      12'hca: data = 64'hb700a100ed00ff;
      12'hcb: data = 64'hb800a300ed00ff;
      12'hcc: data = 64'hb900a400ee00ff;
      12'hcd: data = 64'hba00a600ee00ff;
      12'hce: data = 64'hba00a700ee00ff;
      12'hcf: data = 64'hbb00a900ef00ff;
      12'hd0: data = 64'hbc00aa00ef00ff;
      12'hd1: data = 64'hbd00ac00ef00ff;
      12'hd2: data = 64'hbe00ad00f000ff;
      12'hd3: data = 64'hbf00af00f000ff;
      12'hd4: data = 64'hc000b000f000ff;
      12'hd5: data = 64'hc100b200f100ff;
      12'hd6: data = 64'hc200b400f100ff;
      12'hd7: data = 64'hc200b500f100ff;
      12'hd8: data = 64'hc300b700f200ff;
      12'hd9: data = 64'hc400b800f200ff;
      12'hda: data = 64'hc500ba00f200ff;
      12'hdb: data = 64'hc600bb00f300ff;
      12'hdc: data = 64'hc700bd00f300ff;
      12'hdd: data = 64'hc800be00f300ff;
      12'hde: data = 64'hc800c000f400ff;
      12'hdf: data = 64'hc900c100f400ff;
      12'he0: data = 64'hca00c300f400ff;
      12'he1: data = 64'hcb00c400f500ff;
      12'he2: data = 64'hcc00c600f500ff;
      12'he3: data = 64'hcc00c700f500ff;
      12'he4: data = 64'hcd00c900f600ff;
      12'he5: data = 64'hce00ca00f600ff;
      12'he6: data = 64'hcf00cc00f700ff;
      12'he7: data = 64'hd000ce00f700ff;
      12'he8: data = 64'hd100cf00f700ff;
      12'he9: data = 64'hd100d100f800ff;
      12'hea: data = 64'hd200d200f800ff;
      12'heb: data = 64'hd300d400f800ff;
      12'hec: data = 64'hd400d500f900ff;
      12'hed: data = 64'hd500d700f900ff;
      12'hee: data = 64'hd500d800f900ff;
      12'hef: data = 64'hd600da00fa00ff;
      12'hf0: data = 64'hd700db00fa00ff;
      12'hf1: data = 64'hd800dd00fa00ff;
      12'hf2: data = 64'hd800de00fb00ff;
      12'hf3: data = 64'hd900e000fb00ff;
      12'hf4: data = 64'hda00e100fb00ff;
      12'hf5: data = 64'hdb00e300fc00ff;
      12'hf6: data = 64'hdb00e400fc00ff;
      12'hf7: data = 64'hdc00e600fc00ff;
      12'hf8: data = 64'hdd00e800fd00ff;
      12'hf9: data = 64'hde00e900fd00ff;
      12'hfa: data = 64'hde00eb00fd00ff;
      12'hfb: data = 64'hdf00ec00fe00ff;
      12'hfc: data = 64'he000ee00fe00ff;
      12'hfd: data = 64'he100ef00fe00ff;
      12'hfe: data = 64'he100f100ff00ff;
      12'hff: data = 64'he200f200ff00ff;
      default: data = 64'h0;
    endcase
            
endmodule // top$lanes$0$shader$lut
module top$lanes$0$shader$mul_b(a,b,y);
    
    // Module arguments
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [31:0] t;
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t = a * b + half;
        y_pass = 16'((t + (t >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$0$shader$mul_b
module top$lanes$0$shader$mul_g(a,b,y);
    
    // Module arguments
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [31:0] t;
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t = a * b + half;
        y_pass = 16'((t + (t >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$0$shader$mul_g
module top$lanes$0$shader$mul_r(a,b,y);
    
    // Module arguments
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [31:0] t;
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t = a * b + half;
        y_pass = 16'((t + (t >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$0$shader$mul_r
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
    localparam  scalar = 1'b0;
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
    wire  [63:0] lut$data;
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
    wire  [15:0] mul_r$y;
    reg  [15:0] mul_g$a;
    reg  [15:0] mul_g$b;
    wire  [15:0] mul_g$y;
    reg  [15:0] mul_b$a;
    reg  [15:0] mul_b$b;
    wire  [15:0] mul_b$y;
    reg  [15:0] lit_r$a;
    reg  [15:0] lit_r$b;
    wire  [15:0] lit_r$y;
    reg  [15:0] lit_g$a;
    reg  [15:0] lit_g$b;
    wire  [15:0] lit_g$y;
    reg  [15:0] lit_b$a;
    reg  [15:0] lit_b$b;
    wire  [15:0] lit_b$y;
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
    top$lanes$1$shader$lut lut(
        .address(lut$address),
        .data(lut$data)
    );
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
    top$lanes$1$shader$mul_r mul_r(
        .a(mul_r$a),
        .b(mul_r$b),
        .y(mul_r$y)
    );
    top$lanes$1$shader$mul_g mul_g(
        .a(mul_g$a),
        .b(mul_g$b),
        .y(mul_g$y)
    );
    top$lanes$1$shader$mul_b mul_b(
        .a(mul_b$a),
        .b(mul_b$b),
        .y(mul_b$y)
    );
    top$lanes$1$shader$lit_r lit_r(
        .a(lit_r$a),
        .b(lit_r$b),
        .y(lit_r$y)
    );
    top$lanes$1$shader$lit_g lit_g(
        .a(lit_g$a),
        .b(lit_g$b),
        .y(lit_g$y)
    );
    top$lanes$1$shader$lit_b lit_b(
        .a(lit_b$a),
        .b(lit_b$b),
        .y(lit_b$y)
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
module top$lanes$1$shader$lit_b(a,b,y);
    
    // Module arguments
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [31:0] t;
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t = a * b + half;
        y_pass = 16'((t + (t >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$1$shader$lit_b
module top$lanes$1$shader$lit_g(a,b,y);
    
    // Module arguments
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [31:0] t;
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t = a * b + half;
        y_pass = 16'((t + (t >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$1$shader$lit_g
module top$lanes$1$shader$lit_r(a,b,y);
    
    // Module arguments
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [31:0] t;
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t = a * b + half;
        y_pass = 16'((t + (t >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$1$shader$lit_r
module top$lanes$1$shader$lut(address,data);
    
    // Module arguments
    input wire  [11:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        12'h0: data = 64'h80009900e6;
      12'h1: data = 64'h7f009900e6;
      12'h2: data = 64'h7f009800e6;
      12'h3: data = 64'h7f009800e6;
      12'h4: data = 64'h7e009800e6;
      12'h5: data = 64'h7e009700e6;
      12'h6: data = 64'h7e009700e6;
      12'h7: data = 64'h7d009700e6;
      12'h8: data = 64'h7d009600e6;
      12'h9: data = 64'h7d009600e6;
      12'ha: data = 64'h7c009600e7;
      12'hb: data = 64'h7c009500e7;
      12'hc: data = 64'h7c009500e7;
      12'hd: data = 64'h7b009500e7;
      12'he: data = 64'h7b009500e7;
      12'hf: data = 64'h7b009400e7;
      12'h10: data = 64'h7a009400e7;
      12'h11: data = 64'h7a009400e7;
      12'h12: data = 64'h7a009300e7;
      12'h13: data = 64'h79009300e8;
      12'h14: data = 64'h79009300e8;
      12'h15: data = 64'h79009200e8;
      12'h16: data = 64'h78009200e8;
      12'h17: data = 64'h78009200e8;
      12'h18: data = 64'h78009100e8;
      12'h19: data = 64'h78009100e8;
      12'h1a: data = 64'h77009100e8;
      12'h1b: data = 64'h77009000e8;
      12'h1c: data = 64'h77009000e8;
      12'h1d: data = 64'h76009000e9;
      12'h1e: data = 64'h76008f00e9;
      12'h1f: data = 64'h76008f00e9;
      12'h20: data = 64'h75008f00e9;
      12'h21: data = 64'h75008e00e9;
      12'h22: data = 64'h75008e00e9;
      12'h23: data = 64'h74008e00e9;
      12'h24: data = 64'h74008e00e9;
      12'h25: data = 64'h74008d00e9;
      12'h26: data = 64'h73008d00ea;
      12'h27: data = 64'h73008d00ea;
      12'h28: data = 64'h73008c00ea;
      12'h29: data = 64'h72008c00ea;
      12'h2a: data = 64'h72008c00ea;
      12'h2b: data = 64'h72008b00ea;
      12'h2c: data = 64'h71008b00ea;
      12'h2d: data = 64'h71008b00ea;
      12'h2e: data = 64'h71008a00ea;
      12'h2f: data = 64'h71008a00ea;
      12'h30: data = 64'h70008a00eb;
      12'h31: data = 64'h70008900eb;
      12'h32: data = 64'h70008900eb;
      12'h33: data = 64'h6f008900eb;
      12'h34: data = 64'h6f008800eb;
      12'h35: data = 64'h6f008800eb;
      12'h36: data = 64'h6e008800eb;
      12'h37: data = 64'h6e008700eb;
      12'h38: data = 64'h6e008700eb;
      12'h39: data = 64'h6d008700ec;
      12'h3a: data = 64'h6d008700ec;
      12'h3b: data = 64'h6d008600ec;
      12'h3c: data = 64'h6c008600ec;
      12'h3d: data = 64'h1006c008600ec;
      12'h3e: data = 64'h2006c008500ec;
      12'h3f: data = 64'h3006b008500ec;
      12'h40: data = 64'h3006b008500ec;
      12'h41: data = 64'h4006b008400ec;
      12'h42: data = 64'h5006a008400ed;
      12'h43: data = 64'h6006a008400ed;
      12'h44: data = 64'h7006a008300ed;
      12'h45: data = 64'h8006a008300ed;
      12'h46: data = 64'h90069008300ed;
      12'h47: data = 64'h90069008200ed;
      12'h48: data = 64'ha0069008200ed;
      12'h49: data = 64'hb0068008200ed;
      12'h4a: data = 64'hc0068008100ed;
      12'h4b: data = 64'hd0068008100ed;
      12'h4c: data = 64'he0067008100ee;
      12'h4d: data = 64'hf0067008000ee;
      12'h4e: data = 64'hf0067008000ee;
      12'h4f: data = 64'h100066008000ee;
      12'h50: data = 64'h110066008000ee;
      12'h51: data = 64'h120066007f00ee;
      12'h52: data = 64'h130065007f00ee;
      12'h53: data = 64'h150065007f00ee;
      12'h54: data = 64'h160065007e00ee;
      12'h55: data = 64'h170064007e00ef;
      12'h56: data = 64'h180064007e00ef;
      12'h57: data = 64'h1a0064007d00ef;
      12'h58: data = 64'h1b0063007d00ef;
      12'h59: data = 64'h1c0063007d00ef;
      12'h5a: data = 64'h1d0063007c00ef;
      12'h5b: data = 64'h1e0062007c00ef;
      12'h5c: data = 64'h1f0062007c00ef;
      12'h5d: data = 64'h210062007b00ef;
      12'h5e: data = 64'h220062007b00ef;
      12'h5f: data = 64'h230061007b00f0;
      12'h60: data = 64'h240061007a00f0;
      12'h61: data = 64'h250061007a00f0;
      12'h62: data = 64'h270060007a00f0;
      12'h63: data = 64'h280060007900f0;
      12'h64: data = 64'h290060007900f0;
      12'h65: data = 64'h2a005f007900f0;
      12'h66: data = 64'h2b005f007800f0;
      12'h67: data = 64'h2c005f007800f0;
      12'h68: data = 64'h2e005e007800f1;
      12'h69: data = 64'h2f005e007800f1;
      12'h6a: data = 64'h30005e007700f1;
      12'h6b: data = 64'h31005d007700f1;
      12'h6c: data = 64'h32005d007700f1;
      12'h6d: data = 64'h33005d007600f1;
      12'h6e: data = 64'h35005c007600f1;
      12'h6f: data = 64'h36005c007600f1;
      12'h70: data = 64'h37005c007500f1;
      12'h71: data = 64'h38005b007500f2;
      12'h72: data = 64'h39005b007500f2;
      12'h73: data = 64'h3a005b007400f2;
      12'h74: data = 64'h3c005b007400f2;
      12'h75: data = 64'h3d005a007400f2;
      12'h76: data = 64'h3e005a007300f2;
      12'h77: data = 64'h3f005a007300f2;
      12'h78: data = 64'h400059007300f2;
      12'h79: data = 64'h41005a007500f2;
      12'h7a: data = 64'h42005b007700f3;
      12'h7b: data = 64'h44005b007800f3;
      12'h7c: data = 64'h45005c007a00f3;
      12'h7d: data = 64'h46005c007c00f3;
      12'h7e: data = 64'h47005d007e00f4;
      12'h7f: data = 64'h48005e008000f4;
      12'h80: data = 64'h49005e008200f4;
      12'h81: data = 64'h4a005f008400f4;
      12'h82: data = 64'h4b0060008600f4;
      12'h83: data = 64'h4d0060008800f5;
      12'h84: data = 64'h4e0061008a00f5;
      12'h85: data = 64'h4f0062008c00f5;
      12'h86: data = 64'h500062008e00f5;
      12'h87: data = 64'h510063008f00f5;
      12'h88: data = 64'h520063009100f6;
      12'h89: data = 64'h530064009300f6;
      12'h8a: data = 64'h540065009500f6;
      12'h8b: data = 64'h550065009700f6;
      12'h8c: data = 64'h570066009900f7;
      12'h8d: data = 64'h580067009b00f7;
      12'h8e: data = 64'h590067009d00f7;
      12'h8f: data = 64'h5a0068009f00f7;
      12'h90: data = 64'h5b006900a100f7;
      12'h91: data = 64'h5c006900a300f8;
      12'h92: data = 64'h5d006a00a400f8;
      12'h93: data = 64'h5e006a00a600f8;
      12'h94: data = 64'h5f006b00a800f8;
      12'h95: data = 64'h60006c00aa00f8;
      12'h96: data = 64'h62006c00ac00f9;
      12'h97: data = 64'h63006d00ae00f9;
      12'h98: data = 64'h65006e00b000f9;
      12'h99: data = 64'h67006e00b200f9;
      12'h9a: data = 64'h69006f00b400f9;
      12'h9b: data = 64'h6b007000b600fa;
      12'h9c: data = 64'h6c007000b800fa;
      12'h9d: data = 64'h6e007100ba00fa;
      12'h9e: data = 64'h70007100bb00fa;
      12'h9f: data = 64'h72007200bd00fb;
      12'ha0: data = 64'h74007300bf00fb;
      12'ha1: data = 64'h75007300c100fb;
      12'ha2: data = 64'h77007400c300fb;
      12'ha3: data = 64'h79007500c500fb;
      12'ha4: data = 64'h7b007500c700fc;
      12'ha5: data = 64'h7c007600c900fc;
      12'ha6: data = 64'h7e007700cb00fc;
      12'ha7: data = 64'h80007700cd00fc;
      12'ha8: data = 64'h81007800cf00fc;
      12'ha9: data = 64'h83007800d000fd;
      12'haa: data = 64'h85007900d200fd;
      12'hab: data = 64'h87007a00d400fd;
      12'hac: data = 64'h88007a00d600fd;
      12'had: data = 64'h8a007b00d800fe;
      12'hae: data = 64'h8c007c00da00fe;
      12'haf: data = 64'h8d007c00dc00fe;
      12'hb0: data = 64'h8f007d00de00fe;
      12'hb1: data = 64'h91007e00e000fe;
      12'hb2: data = 64'h92007e00e200ff;
      12'hb3: data = 64'h94007f00e400ff;
      12'hb4: data = 64'h96008000e600ff;
      12'hb5: data = 64'h97008100e600ff;
      12'hb6: data = 64'h99008300e600ff;
      12'hb7: data = 64'h9b008400e700ff;
      12'hb8: data = 64'h9c008600e700ff;
      12'hb9: data = 64'h9e008700e700ff;
      12'hba: data = 64'h9f008900e800ff;
      12'hbb: data = 64'ha1008a00e800ff;
      12'hbc: data = 64'ha3008c00e800ff;
      12'hbd: data = 64'ha4008d00e900ff;
      12'hbe: data = 64'ha6008f00e900ff;
      12'hbf: data = 64'ha7009000e900ff;
      12'hc0: data = 64'ha9009200ea00ff;
      12'hc1: data = 64'haa009300ea00ff;
      12'hc2: data = 64'hac009500ea00ff;
      12'hc3: data = 64'hae009600eb00ff;
      12'hc4: data = 64'haf009800eb00ff;
      12'hc5: data = 64'hb1009a00eb00ff;
      12'hc6: data = 64'hb2009b00ec00ff;
      12'hc7: data = 64'hb4009d00ec00ff;
      12'hc8: data = 64'hb5009e00ec00ff;
      12'hc9: data = 64'hb600a000ed00ff;
      12'hca: data = 64'hb700a100ed00ff;
      12'hcb: data = 64'hb800a300ed00ff;
      12'hcc: data = 64'hb900a400ee00ff;
      12'hcd: data = 64'hba00a600ee00ff;
      12'hce: data = 64'hba00a700ee00ff;
      12'hcf: data = 64'hbb00a900ef00ff;
      12'hd0: data = 64'hbc00aa00ef00ff;
      12'hd1: data = 64'hbd00ac00ef00ff;
      12'hd2: data = 64'hbe00ad00f000ff;
      12'hd3: data = 64'hbf00af00f000ff;
      12'hd4: data = 64'hc000b000f000ff;
      12'hd5: data = 64'hc100b200f100ff;
      12'hd6: data = 64'hc200b400f100ff;
      12'hd7: data = 64'hc200b500f100ff;
      12'hd8: data = 64'hc300b700f200ff;
      12'hd9: data = 64'hc400b800f200ff;
      12'hda: data = 64'hc500ba00f200ff;
      12'hdb: data = 64'hc600bb00f300ff;
      12'hdc: data = 64'hc700bd00f300ff;
      12'hdd: data = 64'hc800be00f300ff;
      12'hde: data = 64'hc800c000f400ff;
      12'hdf: data = 64'hc900c100f400ff;
      12'he0: data = 64'hca00c300f400ff;
      12'he1: data = 64'hcb00c400f500ff;
      12'he2: data = 64'hcc00c600f500ff;
      12'he3: data = 64'hcc00c700f500ff;
      12'he4: data = 64'hcd00c900f600ff;
      12'he5: data = 64'hce00ca00f600ff;
      12'he6: data = 64'hcf00cc00f700ff;
      12'he7: data = 64'hd000ce00f700ff;
      12'he8: data = 64'hd100cf00f700ff;
      12'he9: data = 64'hd100d100f800ff;
      12'hea: data = 64'hd200d200f800ff;
      12'heb: data = 64'hd300d400f800ff;
      12'hec: data = 64'hd400d500f900ff;
      12'hed: data = 64'hd500d700f900ff;
      12'hee: data = 64'hd500d800f900ff;
      12'hef: data = 64'hd600da00fa00ff;
      12'hf0: data = 64'hd700db00fa00ff;
      12'hf1: data = 64'hd800dd00fa00ff;
      12'hf2: data = 64'hd800de00fb00ff;
      12'hf3: data = 64'hd900e000fb00ff;
      12'hf4: data = 64'hda00e100fb00ff;
      12'hf5: data = 64'hdb00e300fc00ff;
      12'hf6: data = 64'hdb00e400fc00ff;
      12'hf7: data = 64'hdc00e600fc00ff;
      12'hf8: data = 64'hdd00e800fd00ff;
      12'hf9: data = 64'hde00e900fd00ff;
      12'hfa: data = 64'hde00eb00fd00ff;
      12'hfb: data = 64'hdf00ec00fe00ff;
      12'hfc: data = 64'he000ee00fe00ff;
      12'hfd: data = 64'he100ef00fe00ff;
      12'hfe: data = 64'he100f100ff00ff;
      12'hff: data = 64'he200f200ff00ff;
      default: data = 64'h0;
    endcase
            
endmodule // top$lanes$1$shader$lut
module top$lanes$1$shader$mul_b(a,b,y);
    
    // Module arguments
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [31:0] t;
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t = a * b + half;
        y_pass = 16'((t + (t >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$1$shader$mul_b
module top$lanes$1$shader$mul_g(a,b,y);
    
    // Module arguments
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [31:0] t;
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t = a * b + half;
        y_pass = 16'((t + (t >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$1$shader$mul_g
module top$lanes$1$shader$mul_r(a,b,y);
    
    // Module arguments
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Local signals
    reg  [31:0] t;
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t = a * b + half;
        y_pass = 16'((t + (t >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$1$shader$mul_r
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
