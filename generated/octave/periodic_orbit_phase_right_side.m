function r = periodic_orbit_phase_right_side(M, K, C, m, e, d, F0, X_b, Omega)
% PERIODIC_ORBIT_PHASE_RIGHT_SIDE  Right side c of a·cos φ + b·sin φ = c [kg m/s], Eq. F3 (derived here, beyond the paper).
%
%   r = periodic_orbit_phase_right_side(M, K, C, m, e, d, F0, X_b, Omega)
%
% Arguments (scalars or arrays of compatible sizes, SI units):
%   M: Main mass M [kg]
%   K: Main stiffness K [N/m]
%   C: Main damping C (underdamped) [N s/m]
%   m: Impact mass m [kg]
%   e: Coefficient of restitution e [1]
%   d: Total clearance d [m]
%   F0: Force amplitude F0 on the main mass [N]
%   X_b: Base-motion amplitude X_b [m]
%   Omega: Forcing frequency Ω [rad/s]
%
% Returns an array of the broadcast size; NaN where the result is not real.
% c = c = \Omega d \left(M e \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} + M e \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} + M e \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) + M e - \frac{M e \left(- \frac{C \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{2 M} + \left(\frac{C \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M} - \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} - M \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} - M \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} - M \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) - M + \frac{M \left(- \frac{C \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{2 M} + \left(\frac{C \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M} - \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + 2 e m \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} + 2 e m \left(- \frac{C e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + e^{- \frac{\pi C}{2 M \Omega}} \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) - \frac{2 e m \left(- \frac{C \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}}{2 M} + \left(\frac{C \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M} - \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}}\right) e^{- \frac{\pi C}{2 M \Omega}} \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{\sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} - 2 m \left(\frac{C \sin{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}}{2 M \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}} + \cos{\left(\frac{\pi \sqrt{- \frac{C^{2}}{4 M^{2}} + \frac{K}{M}}}{\Omega} \right)}\right) e^{- \frac{\pi C}{2 M \Omega}} - 2 m\right)
%
% Generated by derive/periodic_orbit.py through derive/templates/octave/kernel.m.j2.
% Do not edit by hand: change the derivation and run `python -m derive`.
% Mirrors symimpact.generated.periodic_orbit.phase_right_side; operations: 81.
  x_0 = 2*m;
  x_1 = pi./Omega;
  x_2 = 1./M;
  x_3 = C.*x_2/2;
  x_4 = exp(-x_1.*x_3);
  x_5 = sqrt(-C.^2./(4*M.^2) + K.*x_2);
  x_6 = x_1.*x_5;
  x_7 = cos(x_6);
  x_8 = sin(x_6);
  x_9 = 1./x_5;
  x_10 = x_8.*x_9;
  x_11 = x_10.*x_3;
  x_12 = x_11 + x_7;
  x_13 = x_12.*x_4;
  x_14 = -x_11.*x_4 + x_4.*x_7;
  x_15 = M.*x_14;
  x_16 = -x_13.*x_3 + x_4.*(x_3.*x_7 - x_5.*x_8);
  x_17 = x_10.*x_16.*x_4;
  r = Omega.*d.*(M.*e.*x_12.*x_14.*x_4 + M.*e.*x_12.*x_4 + M.*e.*x_14 - M.*e.*x_17 + M.*e - M.*x_13 + M.*x_16.*x_4.*x_8.*x_9 - M + 2*e.*m.*x_12.*x_14.*x_4 + 2*e.*m.*x_14 - e.*x_0.*x_17 - x_0.*x_13 - x_0 - x_13.*x_15 - x_15);
  r = r + zeros(size(M + K + C + m + e + d + F0 + X_b + Omega));
  if ~isreal(r)
    r(imag(r) ~= 0) = NaN;
    r = real(r);
  end
end
