module top$lanes$0$shader(clock,value,invalid,at_edge,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag,r,g,b,a,valid);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] value;
    input wire  invalid;
    input wire  at_edge;
    input wire  gx_neg;
    input wire  [15:0] gx_mag;
    input wire  gy_neg;
    input wire  [15:0] gy_mag;
    input wire  gz_neg;
    input wire  [15:0] gz_mag;
    output reg  [15:0] r;
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
    
    // Stub signals
    reg  [11:0] lut$address;
    wire  [63:0] lut$data = 'h0;
    reg  [14:0] reflectance$address;
    wire  [31:0] reflectance$data = 'h0;
    reg  [15:0] alpha_gm$address;
    wire  [15:0] alpha_gm$data = 'h0;
    reg  [63:0] sqrt$n;
    wire  [31:0] sqrt$root = 'h0;
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
    reg  [31:0] sq_x;
    reg  [31:0] sq_y;
    reg  [31:0] sq_z;
    reg  [31:0] gm_bin;
    reg  [11:0] row;
    reg  [15:0] alpha;
    reg  [15:0] m;
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
        sq_x = gx_mag * gx_mag;
        sq_y = gy_mag * gy_mag;
        sq_z = gz_mag * gz_mag;
        sqrt$n = 64'(sq_x) + 64'(sq_y) + 64'(sq_z);
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
        if (m >= 'h1) begin
            bl = 'h1;
        end
        if (m >= 'h2) begin
            bl = 'h2;
        end
        if (m >= 'h4) begin
            bl = 'h3;
        end
        if (m >= 'h8) begin
            bl = 'h4;
        end
        if (m >= 'h10) begin
            bl = 'h5;
        end
        if (m >= 'h20) begin
            bl = 'h6;
        end
        if (m >= 'h40) begin
            bl = 'h7;
        end
        if (m >= 'h80) begin
            bl = 'h8;
        end
        if (m >= 'h100) begin
            bl = 'h9;
        end
        if (m >= 'h200) begin
            bl = 'ha;
        end
        if (m >= 'h400) begin
            bl = 'hb;
        end
        if (m >= 'h800) begin
            bl = 'hc;
        end
        if (m >= 'h1000) begin
            bl = 'hd;
        end
        if (m >= 'h2000) begin
            bl = 'he;
        end
        if (m >= 'h4000) begin
            bl = 'hf;
        end
        if (m >= 'h8000) begin
            bl = 'h10;
        end
        s = 'h0;
        if (bl > 'h4) begin
            s = bl - 'h4;
        end
        half = 'h0;
        if (s > 'h0) begin
            half = (32'('h1) << s) >> 'h1;
        end
        qx = (32'(gx_mag) + half) >> s;
        if (gx_neg & (s > 'h0)) begin
            qx = (32'(gx_mag) + half - 'h1) >> s;
        end
        qy = (32'(gy_mag) + half) >> s;
        if (gy_neg & (s > 'h0)) begin
            qy = (32'(gy_mag) + half - 'h1) >> s;
        end
        qz = (32'(gz_mag) + half) >> s;
        if (gz_neg & (s > 'h0)) begin
            qz = (32'(gz_mag) + half - 'h1) >> s;
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
        r = r_q$q;
        g = g_q$q;
        b = b_q$q;
        a = a_q$q;
        valid = valid_q$q;
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
    input wire  [15:0] gx_mag;
    input wire  gy_neg;
    input wire  [15:0] gy_mag;
    input wire  gz_neg;
    input wire  [15:0] gz_mag;
    output reg  [15:0] r;
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
    
    // Stub signals
    reg  [11:0] lut$address;
    wire  [63:0] lut$data = 'h0;
    reg  [14:0] reflectance$address;
    wire  [31:0] reflectance$data = 'h0;
    reg  [15:0] alpha_gm$address;
    wire  [15:0] alpha_gm$data = 'h0;
    reg  [63:0] sqrt$n;
    wire  [31:0] sqrt$root = 'h0;
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
    reg  [31:0] sq_x;
    reg  [31:0] sq_y;
    reg  [31:0] sq_z;
    reg  [31:0] gm_bin;
    reg  [11:0] row;
    reg  [15:0] alpha;
    reg  [15:0] m;
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
        sq_x = gx_mag * gx_mag;
        sq_y = gy_mag * gy_mag;
        sq_z = gz_mag * gz_mag;
        sqrt$n = 64'(sq_x) + 64'(sq_y) + 64'(sq_z);
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
        if (m >= 'h1) begin
            bl = 'h1;
        end
        if (m >= 'h2) begin
            bl = 'h2;
        end
        if (m >= 'h4) begin
            bl = 'h3;
        end
        if (m >= 'h8) begin
            bl = 'h4;
        end
        if (m >= 'h10) begin
            bl = 'h5;
        end
        if (m >= 'h20) begin
            bl = 'h6;
        end
        if (m >= 'h40) begin
            bl = 'h7;
        end
        if (m >= 'h80) begin
            bl = 'h8;
        end
        if (m >= 'h100) begin
            bl = 'h9;
        end
        if (m >= 'h200) begin
            bl = 'ha;
        end
        if (m >= 'h400) begin
            bl = 'hb;
        end
        if (m >= 'h800) begin
            bl = 'hc;
        end
        if (m >= 'h1000) begin
            bl = 'hd;
        end
        if (m >= 'h2000) begin
            bl = 'he;
        end
        if (m >= 'h4000) begin
            bl = 'hf;
        end
        if (m >= 'h8000) begin
            bl = 'h10;
        end
        s = 'h0;
        if (bl > 'h4) begin
            s = bl - 'h4;
        end
        half = 'h0;
        if (s > 'h0) begin
            half = (32'('h1) << s) >> 'h1;
        end
        qx = (32'(gx_mag) + half) >> s;
        if (gx_neg & (s > 'h0)) begin
            qx = (32'(gx_mag) + half - 'h1) >> s;
        end
        qy = (32'(gy_mag) + half) >> s;
        if (gy_neg & (s > 'h0)) begin
            qy = (32'(gy_mag) + half - 'h1) >> s;
        end
        qz = (32'(gz_mag) + half) >> s;
        if (gz_neg & (s > 'h0)) begin
            qz = (32'(gz_mag) + half - 'h1) >> s;
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
        r = r_q$q;
        g = g_q$q;
        b = b_q$q;
        a = a_q$q;
        valid = valid_q$q;
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
    input wire  [15:0] gx_mag;
    input wire  gy_neg;
    input wire  [15:0] gy_mag;
    input wire  gz_neg;
    input wire  [15:0] gz_mag;
    output reg  [15:0] r;
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
    
    // Stub signals
    reg  [11:0] lut$address;
    wire  [63:0] lut$data = 'h0;
    reg  [14:0] reflectance$address;
    wire  [31:0] reflectance$data = 'h0;
    reg  [15:0] alpha_gm$address;
    wire  [15:0] alpha_gm$data = 'h0;
    reg  [63:0] sqrt$n;
    wire  [31:0] sqrt$root = 'h0;
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
    reg  [31:0] sq_x;
    reg  [31:0] sq_y;
    reg  [31:0] sq_z;
    reg  [31:0] gm_bin;
    reg  [11:0] row;
    reg  [15:0] alpha;
    reg  [15:0] m;
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
        sq_x = gx_mag * gx_mag;
        sq_y = gy_mag * gy_mag;
        sq_z = gz_mag * gz_mag;
        sqrt$n = 64'(sq_x) + 64'(sq_y) + 64'(sq_z);
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
        if (m >= 'h1) begin
            bl = 'h1;
        end
        if (m >= 'h2) begin
            bl = 'h2;
        end
        if (m >= 'h4) begin
            bl = 'h3;
        end
        if (m >= 'h8) begin
            bl = 'h4;
        end
        if (m >= 'h10) begin
            bl = 'h5;
        end
        if (m >= 'h20) begin
            bl = 'h6;
        end
        if (m >= 'h40) begin
            bl = 'h7;
        end
        if (m >= 'h80) begin
            bl = 'h8;
        end
        if (m >= 'h100) begin
            bl = 'h9;
        end
        if (m >= 'h200) begin
            bl = 'ha;
        end
        if (m >= 'h400) begin
            bl = 'hb;
        end
        if (m >= 'h800) begin
            bl = 'hc;
        end
        if (m >= 'h1000) begin
            bl = 'hd;
        end
        if (m >= 'h2000) begin
            bl = 'he;
        end
        if (m >= 'h4000) begin
            bl = 'hf;
        end
        if (m >= 'h8000) begin
            bl = 'h10;
        end
        s = 'h0;
        if (bl > 'h4) begin
            s = bl - 'h4;
        end
        half = 'h0;
        if (s > 'h0) begin
            half = (32'('h1) << s) >> 'h1;
        end
        qx = (32'(gx_mag) + half) >> s;
        if (gx_neg & (s > 'h0)) begin
            qx = (32'(gx_mag) + half - 'h1) >> s;
        end
        qy = (32'(gy_mag) + half) >> s;
        if (gy_neg & (s > 'h0)) begin
            qy = (32'(gy_mag) + half - 'h1) >> s;
        end
        qz = (32'(gz_mag) + half) >> s;
        if (gz_neg & (s > 'h0)) begin
            qz = (32'(gz_mag) + half - 'h1) >> s;
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
        r = r_q$q;
        g = g_q$q;
        b = b_q$q;
        a = a_q$q;
        valid = valid_q$q;
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
    input wire  [15:0] gx_mag;
    input wire  gy_neg;
    input wire  [15:0] gy_mag;
    input wire  gz_neg;
    input wire  [15:0] gz_mag;
    output reg  [15:0] r;
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
    
    // Stub signals
    reg  [11:0] lut$address;
    wire  [63:0] lut$data = 'h0;
    reg  [14:0] reflectance$address;
    wire  [31:0] reflectance$data = 'h0;
    reg  [15:0] alpha_gm$address;
    wire  [15:0] alpha_gm$data = 'h0;
    reg  [63:0] sqrt$n;
    wire  [31:0] sqrt$root = 'h0;
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
    reg  [31:0] sq_x;
    reg  [31:0] sq_y;
    reg  [31:0] sq_z;
    reg  [31:0] gm_bin;
    reg  [11:0] row;
    reg  [15:0] alpha;
    reg  [15:0] m;
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
        sq_x = gx_mag * gx_mag;
        sq_y = gy_mag * gy_mag;
        sq_z = gz_mag * gz_mag;
        sqrt$n = 64'(sq_x) + 64'(sq_y) + 64'(sq_z);
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
        if (m >= 'h1) begin
            bl = 'h1;
        end
        if (m >= 'h2) begin
            bl = 'h2;
        end
        if (m >= 'h4) begin
            bl = 'h3;
        end
        if (m >= 'h8) begin
            bl = 'h4;
        end
        if (m >= 'h10) begin
            bl = 'h5;
        end
        if (m >= 'h20) begin
            bl = 'h6;
        end
        if (m >= 'h40) begin
            bl = 'h7;
        end
        if (m >= 'h80) begin
            bl = 'h8;
        end
        if (m >= 'h100) begin
            bl = 'h9;
        end
        if (m >= 'h200) begin
            bl = 'ha;
        end
        if (m >= 'h400) begin
            bl = 'hb;
        end
        if (m >= 'h800) begin
            bl = 'hc;
        end
        if (m >= 'h1000) begin
            bl = 'hd;
        end
        if (m >= 'h2000) begin
            bl = 'he;
        end
        if (m >= 'h4000) begin
            bl = 'hf;
        end
        if (m >= 'h8000) begin
            bl = 'h10;
        end
        s = 'h0;
        if (bl > 'h4) begin
            s = bl - 'h4;
        end
        half = 'h0;
        if (s > 'h0) begin
            half = (32'('h1) << s) >> 'h1;
        end
        qx = (32'(gx_mag) + half) >> s;
        if (gx_neg & (s > 'h0)) begin
            qx = (32'(gx_mag) + half - 'h1) >> s;
        end
        qy = (32'(gy_mag) + half) >> s;
        if (gy_neg & (s > 'h0)) begin
            qy = (32'(gy_mag) + half - 'h1) >> s;
        end
        qz = (32'(gz_mag) + half) >> s;
        if (gz_neg & (s > 'h0)) begin
            qz = (32'(gz_mag) + half - 'h1) >> s;
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
        r = r_q$q;
        g = g_q$q;
        b = b_q$q;
        a = a_q$q;
        valid = valid_q$q;
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
